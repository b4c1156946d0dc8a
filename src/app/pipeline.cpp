#include "app/pipeline.h"

#include "app/camera_views.h"

namespace rt::app {

void takeSolve(PipelineResult& result, SolveOutcome solve) {
  result.solverName = std::move(solve.solverName);
  result.B = std::move(solve.B);
  result.history = std::move(solve.history);
  result.status = solve.status;
  result.iterations = solve.iterations;
  result.residual = solve.residual;
}

PipelineResult runScenePipeline(Pipeline& pipeline, const Scene& scene, const PipelineSettings& settings,
                                Progress& progress) {
  PipelineSettings replayed = settings;
  replayed.recordHistory = true;  // the window steps through the iterations
  PipelineOutput out = pipeline.run(scene, replayed, progress);
  PipelineResult result;
  result.scene = out.scene;
  result.mesh = out.mesh;
  result.F = out.F;
  result.formFactorMethod = out.formFactorMethod;
  result.formFactorStats = out.formFactorStats;
  result.formFactorsReused = out.formFactorsReused;
  result.note = out.note;
  result.camera = sceneCamera(*out.scene);
  result.title = out.scene->name;
  takeSolve(result, std::move(out.solve));
  return result;
}

}  // namespace rt::app
