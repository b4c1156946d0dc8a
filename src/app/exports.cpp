#include "app/exports.h"

#include <filesystem>
#include <stdexcept>

#include "app/lesson_session.h"
#include "core/io/matrix_export.h"
#include "core/solvers/radiosity_system.h"
#include "viz/chart.h"

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
  int written = 0;
  const int steps = static_cast<int>(lesson.steps.size());
  for (int s = 0; s < steps; ++s) {
    if (onStep) onStep(s, steps);
    if (progress.cancelled()) throw Cancelled();
    const lesson::Step& step = lesson.steps[static_cast<std::size_t>(s)];
    if (step.stage == lesson::Stage::Text) continue;
    const PipelineResult result = library.runStep(lessonIndex, s, step.parameters, {}, {}, progress);
    if (!result.mesh) continue;
    const std::string base = step.figure.empty() ? lesson.id + "-step" + std::to_string(s + 1) : step.figure;
    viz::SceneViewOptions options;
    options.image.width = width;
    options.image.height = height;
    options.image.exposure = step.parameters.exposure;
    options.image.toneMap =
        step.parameters.toneMap == "reinhard" ? viz::ToneMap::Reinhard : viz::ToneMap::LinearClamp;
    options.image.srgbGamma = step.parameters.gamma;
    options.image.smooth = step.parameters.smooth;
    options.image.showEdges = step.parameters.edges;
    options.caption = step.title;
    viz::SceneViewData data;
    data.B = result.B;
    exportSceneFigure(*result.mesh, result.camera, data, options,
                      (fs::path(folder) / (base + ".png")).string());
    ++written;
    if (result.history.size() > 1) {
      viz::Series series;
      series.name = result.solverName;
      for (const IterationRecord& r : result.history) {
        series.x.push_back(r.iteration);
        series.y.push_back(std::max(r.residual, 1e-300));
      }
      viz::ChartOptions chart;
      chart.title = step.title + ": convergence";
      chart.xLabel = "iteration";
      chart.yLabel = "relative residual";
      chart.logY = true;
      viz::writeLineChart({series}, chart, (fs::path(folder) / (base + "-convergence.svg")).string());
      ++written;
    }
  }
  return written;
}

}  // namespace rt::app
