// The general pipeline the app runs for a scene: apply the reader's overrides (reflectance, light), mesh,
// form factors, solve with the history recorded for replay. It only glues core calls together, and it reuses
// the previous form-factor matrix whenever the geometry and the form-factor settings are unchanged: changing
// a reflectance or the light re-solves without recomputing F. No Qt: it runs on a worker thread.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/formfactor/formfactor_method.h"
#include "core/progress.h"
#include "core/scene.h"
#include "core/solvers/solver.h"

namespace rt::app {

struct PipelineSettings {
  MeshOptions mesh;
  std::string method = "analytic";  // form-factor method
  FormFactorOptions formFactors;
  std::string solver;  // empty: chooseSolver(n)
  SolverOptions solverOptions;
  std::map<std::string, Rgb> reflectance;  // surface name -> reflectance
  double lightScale = 1.0;                 // multiplies every emission
};

struct PipelineResult {
  std::shared_ptr<const Scene> scene;  // with the overrides applied
  std::shared_ptr<const Mesh> mesh;
  std::shared_ptr<const FormFactorMatrix> F;  // null when no form-factor method was available
  std::string formFactorKey;                  // what F depends on: geometry, method and its options
  std::string formFactorMethod;               // the method that computed F (empty without F)
  FormFactorStats formFactorStats;
  bool formFactorsReused = false;
  std::string solverName;
  RgbField B;
  std::vector<IterationRecord> history;
  SolverStatus status = SolverStatus::InvalidInput;
  int iterations = 0;
  double residual = 0;
  std::string note;        // why the result is an approximation, when it is one
  bool materials = false;  // no radiosity to show (a benchmark step): the 3D view shows the materials
  Camera camera;
  // Lesson steps: the title, the step's text with its placeholders filled in, and what the step runner
  // returned.
  std::string title;
  std::string text;
  std::shared_ptr<const void>
      stepResult;  // a lesson::StepResult (kept opaque so that core users need no lesson)
  // Compare mode: the same scene with the compared settings (another solver or form-factor method).
  std::shared_ptr<const PipelineResult> compared;

  bool valid() const { return mesh != nullptr; }
};

// Applies the reflectance overrides (unknown surface names throw InputError) and the light scale.
Scene applyOverrides(const Scene& scene, const PipelineSettings& settings);

// Direct light plus the classic ambient term: B_i = E_i + rho_i * ambient, ambient = (sum E A / sum A) / (1 -
// rho_avg). Shown when no form-factor method or solver is available, so that the view is never empty.
RgbField ambientEstimate(const Mesh& mesh);

// Solves result.mesh with result.F, recording the history for replay; fills B, history, status, iterations,
// residual and solverName (falls back to the ambient estimate, with a note, when the solver is unknown).
void solveWithHistory(PipelineResult& result, const std::string& solverName, SolverOptions options,
                      Progress& progress);

// May throw Cancelled (then nothing of `previous` is touched) and InputError.
PipelineResult runPipeline(const Scene& scene, const PipelineSettings& settings, Progress& progress,
                           const PipelineResult* previous = nullptr);

}  // namespace rt::app
