#include "app/step_figures.h"

#include <QDir>
#include <exception>
#include <memory>
#include <mutex>

#include "app/figure_thread.h"
#include "app/render_lock.h"
#include "viz/lesson_figures.h"

namespace rt::app {

lesson::Step figureStep(const lesson::Step& step) {
  lesson::Step figures = step;
  figures.views.clear();
  for (lesson::View v : step.views)
    if (v != lesson::View::Scene && v != lesson::View::Walkthrough) figures.views.push_back(v);
  return figures;
}

StepFigures drawStepFigures(const lesson::Lesson& lesson, const lesson::Step& step,
                            const lesson::StepResult& result, const QString& folder, QSize size) {
  StepFigures drawn;
  const lesson::Step others = figureStep(step);
  if (others.views.empty()) return drawn;
  viz::StepFigureSettings settings;
  settings.width = size.width();
  settings.height = size.height();
  std::vector<lesson::RenderedFigure> figures;
  try {
    const std::lock_guard lock(renderMutex());
    onFigureThread(
        [&] { figures = viz::renderStepFigures(lesson, others, result, folder.toStdString(), settings); });
  } catch (const std::exception& e) {
    drawn.error = QString::fromStdString(e.what());
    return drawn;
  }
  const auto files = others.figureFiles();
  for (std::size_t k = 0; k < files.size(); ++k) {
    const QString path = QDir(folder).filePath(QString::fromStdString(files[k]));
    QImage image(path);
    if (image.isNull()) continue;  // vector-only formats are not shown here
    drawn.images.push_back(image);
    drawn.files << path;
    drawn.captions << (k < figures.size() ? QString::fromStdString(figures[k].caption) : QString());
  }
  return drawn;
}

void addStepFigures(PipelineResult& result, const lesson::Lesson& lesson, const lesson::Step& step,
                    const lesson::StepParameters& parameters, const QString& folder, QSize size,
                    Progress& progress) {
  if (!result.stepResult || folder.isEmpty() || figureStep(step).views.empty()) return;
  if (progress.cancelled()) throw Cancelled();
  progress.report(1.0, "drawing the figures");
  lesson::Step shown = step;
  shown.parameters = parameters;
  result.figures = std::make_shared<StepFigures>(drawStepFigures(
      lesson, shown, *std::static_pointer_cast<const lesson::StepResult>(result.stepResult), folder, size));
}

}  // namespace rt::app
