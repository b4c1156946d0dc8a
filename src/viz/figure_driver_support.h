// Pieces the figure driver's views share: the scene with its mesh and a pipeline for its form factors,
// solving with the history kept, the default elements a view is about, the notes it prints. Internal to viz.
#pragma once

#include <memory>
#include <sstream>
#include <string>

#include "core/pipeline/pipeline.h"
#include "core/refine/refine.h"
#include "core/solvers/solver.h"
#include "viz/figure_request.h"
#include "viz/scene_view.h"

namespace rt::viz::detail {

struct Computed {
  const Scene& scene;
  Mesh mesh;
  mutable Pipeline pipeline;  // F of the request's methods, computed once each
};

template <class... Parts>
void say(const FigureRequest& a, const Parts&... parts) {
  if (!a.note) return;
  std::ostringstream out;
  (out << ... << parts);
  a.note(out.str());
}

Progress& progressOf(const FigureRequest& a);
FormFactorMatrix formFactors(const Computed& c, const std::string& name, const FigureRequest& a);
std::unique_ptr<Solver> runSolver(const std::string& name, const RadiositySystem& system, int maxIterations,
                                  double tolerance, RgbField& B);
int firstEmitter(const Mesh& mesh);
// The element that sees `target` best (largest point-to-polygon form factor from its centroid).
int bestViewer(const Mesh& mesh, int target);
void checkElement(int e, const Mesh& mesh, const char* option);
SceneViewOptions sceneOptions(const FigureRequest& a);
RefinedSolution refined(const Computed& c, const FigureRequest& a, RefineMode mode);

void sceneFigure(const Computed& c, const FigureRequest& a);
void formFactorFigure(const Computed& c, const FigureRequest& a);
void matrixFigure(const Computed& c, const FigureRequest& a);
void nusseltFigure(const Computed& c, const FigureRequest& a);
void hemicubeFigure(const Computed& c, const FigureRequest& a);
void raysFigure(const Computed& c, const FigureRequest& a);
void visibilityFigure(const Computed& c, const FigureRequest& a);
void linksFigure(const Computed& c, const FigureRequest& a);
void discontinuityFigure(const Computed& c, const FigureRequest& a);
void chartFigure(const Computed& c, const FigureRequest& a);

}  // namespace rt::viz::detail
