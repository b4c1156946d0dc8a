// Running a lesson step: load the scene (once), apply the step's material overrides, mesh it, compute what
// the stage needs and return a StepResult. Form factors are cached under (scene, mesh options, method, method
// options): steps that only change materials, the light or the solver never recompute F.
#pragma once

#include <any>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "core/input_error.h"
#include "core/pipeline/pipeline.h"
#include "core/progress.h"
#include "lesson/lesson.h"
#include "lesson/step_result.h"

namespace rt::lesson {

// A step names a method the registries know of but this build does not include (e.g. "exact" without CGAL).
class MethodUnavailable : public InputError {
 public:
  using InputError::InputError;
};

struct RunOptions {
  // Small parameters for quick renders (the documentation test): subdivision <= 3, hemicube resolution <= 32,
  // samples <= 8, sweep values <= 64, refinement kept small; a pathtrace step's paths, image size and gather
  // rays a quarter. Lists keep their entries, so placeholders still resolve.
  bool quick = false;
  std::string outputDir;  // where a matrix step writes its export (empty: the export is skipped)
  // Keep every iteration of the run a reader replays (StepResult::replay): the app steps through them.
  bool recordHistory = false;
};

class StepRunner {
 public:
  explicit StepRunner(std::string scenesDir, RunOptions options = {});

  // Throws InputError naming the lesson file and the line of the parameter at fault (unknown method, element
  // out of range, a method the build does not have...), Cancelled when progress asks.
  StepResult run(const Lesson& lesson, const Step& step, Progress& progress = noProgress());

  // How many times F was actually computed (the rest came from the cache).
  int formFactorComputations() const { return pipeline_.formFactorComputations(); }
  // How many steps were run (each opening of a step in the app is one).
  int stepRuns() const { return stepRuns_; }
  const RunOptions& options() const { return options_; }
  Pipeline& pipeline() { return pipeline_; }

  // Pictures a stage computed last for `key` (everything they depend on, written out): the steps of a lesson
  // showing other views of the same traced pictures trace them once, and a reflection step whose ambient
  // light changes does not render its local picture again. Null if none of type T was kept for `key`.
  template <class T>
  std::shared_ptr<const T> keptPictures(const std::string& key) const {
    for (const auto& [k, pictures] : kept_)
      if (k == key)
        if (const auto* typed = std::any_cast<std::shared_ptr<const T>>(&pictures)) return *typed;
    return nullptr;
  }
  template <class T>
  void keepPictures(const std::string& key, std::shared_ptr<const T> pictures) {
    keep(key, std::move(pictures));
  }

  // The form factors for a mesh, through the pipeline's cache. Throws std::invalid_argument for a method
  // this build does not have.
  std::shared_ptr<const FormFactorMatrix> formFactors(const Mesh& mesh, const std::string& method,
                                                      const FormFactorOptions& options,
                                                      FormFactorStats& stats, Progress& progress);

  // A scene file relative to the scenes folder, loaded once. Throws InputError when it does not load.
  const Scene& scene(const std::string& relativePath);

 private:
  void keep(const std::string& key, std::any pictures);

  std::string scenesDir_;
  RunOptions options_;
  std::map<std::string, Scene> scenes_;
  Pipeline pipeline_{16};
  int stepRuns_ = 0;
  // A few pictures only: large images take memory, and a reader's changes make old keys useless.
  std::deque<std::pair<std::string, std::any>> kept_;
};

// The text of a step with its placeholders filled in from the result (InputError at the placeholder's line
// when the step computes no such value).
std::string resolvedText(const Lesson& lesson, const Step& step, const StepResult& result);

// The step's `caption` with its placeholders filled in the same way; empty when the step gives none.
std::string resolvedCaption(const Lesson& lesson, const Step& step, const StepResult& result);

}  // namespace rt::lesson
