// What the right pane of compare mode changes against the left one: the solver, the form-factor method, or
// the mesh (half or twice the subdivision, or a mesh that follows the light: adaptive, hierarchical,
// discontinuity). One parameter at a time reads best in class, but any combination is allowed. No Qt: the
// compared result is computed on the worker thread with the left one.
#pragma once

#include <string>
#include <vector>

#include "app/pipeline.h"
#include "lesson/lesson.h"

namespace rt::app {

struct CompareChoice {
  std::string solver;  // empty: the left pane's
  std::string method;  // empty: the left pane's
  std::string mesh;    // empty: the left pane's; "coarser", "finer" or a refine mode ("adaptive", ...)
  bool changesSomething() const { return !solver.empty() || !method.empty() || !mesh.empty(); }
  // The mesh is refined by core/refine (its own form factors and solver) rather than subdivided uniformly.
  bool refinesMesh() const;
};

// The mesh choices the compare pane offers, in menu order.
std::vector<std::string> compareMeshChoices();

// Half ("coarser") or twice ("finer") the subdivision of `options`; other choices leave it unchanged.
MeshOptions scaledMesh(MeshOptions options, const std::string& choice);
// The same for a lesson step's parameters (subdivide or maxEdge).
void scaleStepMesh(lesson::StepParameters& parameters, const std::string& choice);

// The scene solved on a mesh refined by core/refine (`choice` names the mode). `quick` keeps it small
// (tests). The result has no form-factor matrix and no iteration history: its pane shows the final
// radiosity at every tick of the shared clock.
PipelineResult runRefinedPipeline(const std::shared_ptr<const Scene>& scene, const std::string& choice,
                                  bool quick, Progress& progress);

// "gauss-seidel, 400 elements": what a pane shows in its corner, so that two panes can be told apart. With
// `other` (the pane beside it) the form-factor method is named when the two differ: "gauss-seidel, hemicube
// F, 400 elements".
std::string paneCaption(const PipelineResult& result, const PipelineResult* other = nullptr);

}  // namespace rt::app
