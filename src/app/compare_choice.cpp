#include "app/compare_choice.h"

#include "app/camera_views.h"
#include "core/refine/refine.h"
#include "lesson/step_settings.h"

namespace rt::app {

bool CompareChoice::refinesMesh() const {
  return !mesh.empty() && mesh != "coarser" && mesh != "finer";
}

std::vector<std::string> compareMeshChoices() {
  return {"coarser", "finer", "adaptive", "hierarchical", "discontinuity"};
}

MeshOptions scaledMesh(MeshOptions options, const std::string& choice) {
  const bool coarser = choice == "coarser", finer = choice == "finer";
  if (!coarser && !finer) return options;
  switch (options.mode) {
    case MeshOptions::Mode::Count:
      options.count = coarser ? std::max(1, options.count / 2) : options.count * 2;
      break;
    case MeshOptions::Mode::MaxEdge:
      options.maxEdge = coarser ? options.maxEdge * 2 : options.maxEdge / 2;
      break;
    case MeshOptions::Mode::None:  // one element per patch: nothing coarser exists
      if (finer) options.mode = MeshOptions::Mode::Count, options.count = 2;
      break;
  }
  return options;
}

void scaleStepMesh(lesson::StepParameters& p, const std::string& choice) {
  lesson::setMeshOptions(p, scaledMesh(lesson::meshOptionsFor(p), choice));
}

PipelineResult runRefinedPipeline(const std::shared_ptr<const Scene>& scene, const std::string& choice,
                                  bool quick, Progress& progress) {
  RefineOptions options;
  options.mode = refineModeFromString(choice);
  if (quick) {
    options.maxPasses = 2;
    options.maxElements = 300;
    options.refinementRounds = 1;
    options.visibilitySamples = 4;
  }
  RefinedSolution solution = solveRefined(*scene, options, progress);
  PipelineResult result;
  result.scene = scene;
  result.camera = sceneCamera(*scene);
  result.B = std::move(solution.B);
  result.mesh = std::make_shared<Mesh>(std::move(solution.mesh));
  result.title = choice;  // the pane caption adds the element count
  result.note.clear();
  result.status = SolverStatus::Success;
  result.formFactorStats = {};
  result.iterations = static_cast<int>(solution.stats.passes.size());
  return result;
}

std::string paneCaption(const PipelineResult& result, const PipelineResult* other) {
  std::string name = result.solverName.empty() ? result.title : result.solverName;
  if (other && !result.formFactorMethod.empty() && !other->formFactorMethod.empty() &&
      result.formFactorMethod != other->formFactorMethod)
    name += (name.empty() ? "" : ", ") + result.formFactorMethod + " F";
  if (result.mesh)
    name += (name.empty() ? "" : ", ") + std::to_string(result.mesh->size()) +
            (result.mesh->size() == 1 ? " element" : " elements");
  return name;
}

}  // namespace rt::app
