#include "app/exports.h"

#include <filesystem>
#include <stdexcept>

#include "app/lesson_session.h"
#include "core/io/matrix_export.h"
#include "core/solvers/radiosity_system.h"
#include "lesson/step_result.h"
#include "viz/lesson_figures.h"

namespace rt::app {

void exportSceneFigure(const Mesh& mesh, const Camera& camera, const viz::SceneViewData& data,
                       const viz::SceneViewOptions& options, const std::string& path) {
  viz::writeSceneFigure(mesh, camera, data, options, path);
}

void exportMatrix(const PipelineResult& result, const std::string& which, const std::string& path) {
  if (which == "B") {
    if (result.B.rows() == 0) throw std::runtime_error("there is no radiosity to export");
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> B = result.B;
    writeMatrix(B, path);
    return;
  }
  if (!result.F) throw std::runtime_error("this step has no form-factor matrix to export");
  if (which == "K") {
    // K for the first (red) channel, as `radiosity matrix` writes it.
    const FormFactorMatrix K = FormFactorMatrix::Identity(result.F->rows(), result.F->cols()) -
                               result.mesh->reflectance.col(0).asDiagonal() * (*result.F);
    writeMatrix(K, path);
    return;
  }
  writeMatrix(*result.F, path);
}

int exportLessonFigures(LessonLibrary& library, int lessonIndex, const std::string& folder, int width,
                        int height, Progress& progress, const std::function<void(int, int)>& onStep) {
  namespace fs = std::filesystem;
  fs::create_directories(folder);
  const lesson::Lesson& lesson = library.lessons().at(static_cast<std::size_t>(lessonIndex));
  viz::StepFigureSettings settings;
  settings.width = width;
  settings.height = height;
  int written = 0;
  const int steps = static_cast<int>(lesson.steps.size());
  for (int s = 0; s < steps; ++s) {
    if (onStep) onStep(s, steps);
    if (progress.cancelled()) throw Cancelled();
    const lesson::Step& step = lesson.steps[static_cast<std::size_t>(s)];
    if (step.stage == lesson::Stage::Text || step.figureFiles().empty()) continue;
    const PipelineResult result = library.runStep(lessonIndex, s, step.parameters, {}, {}, progress);
    auto stepResult = std::static_pointer_cast<const lesson::StepResult>(result.stepResult);
    if (!stepResult) continue;
    // The same drawing as `radiosity lesson render`: one file per view, named by the step's figure.
    written += static_cast<int>(viz::renderStepFigures(lesson, step, *stepResult, folder, settings).size());
  }
  return written;
}

}  // namespace rt::app
