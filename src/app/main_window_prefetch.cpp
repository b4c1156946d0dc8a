// MainWindow: the next step computed ahead while the reader reads this one, its figures drawn with it on the
// worker thread. Its result joins the recent results and its figures the figures pane's memory, so that Page
// Down shows it as a revisit is shown: from memory, without waiting for the computation or the figures.
#include <QApplication>
#include <QElapsedTimer>
#include <QThread>

#include "app/computation_runner.h"
#include "app/figures_pane.h"
#include "app/lesson_session.h"
#include "app/main_window.h"
#include "app/step_figures.h"
#include "lesson/step_result.h"

namespace rt::app {

bool MainWindow::prefetching() const {
  return prefetch_ && prefetch_->busy();
}

bool MainWindow::waitUntilPrefetched(int timeoutMs) {
  QElapsedTimer timer;
  timer.start();
  while (prefetching()) {
    if (timer.elapsed() > timeoutMs) return false;
    QApplication::processEvents(QEventLoop::AllEvents, 50);
    QThread::msleep(2);
  }
  QApplication::processEvents();
  return true;
}

void MainWindow::prefetchNextStep() {
  if (blocking_ || compare_ || mode_ != Mode::Lesson || busy() || prefetching() || figureExport_ ||
      !options_.screenshot.isEmpty())
    return;
  const auto& lessons = library_->lessons();
  int l = lesson_, s = step_ + 1;
  if (s >= static_cast<int>(lessons[static_cast<std::size_t>(l)].steps.size())) ++l, s = 0;
  if (l >= static_cast<int>(lessons.size())) return;
  const lesson::Step& next = lessons[static_cast<std::size_t>(l)].steps[static_cast<std::size_t>(s)];
  if (next.stage == lesson::Stage::Exercise || next.stage == lesson::Stage::Text ||
      next.stage == lesson::Stage::Benchmark || isLongStep(l, s))
    return;
  // The parameters openStep gives a step it opens: the step's own.
  const lesson::StepParameters parameters = next.parameters;
  const QString key = recentKey(l, s, parameters);
  if (recent_.find(key)) return;
  prefetched_ = {key, l, s, lesson_, step_};
  LessonLibrary* library = library_.get();
  const QString folder = figures_->newFolder();
  const QSize size = figures_->drawSize();
  prefetch_->start([library, l, s, parameters, folder, size](Progress& progress) {
    PipelineResult result = library->runStep(l, s, parameters, CompareChoice{}, progress);
    const lesson::Lesson& lesson = library->lessons()[static_cast<std::size_t>(l)];
    addStepFigures(result, lesson, lesson.steps[static_cast<std::size_t>(s)], parameters, folder, size,
                   progress);
    return result;
  });
}

void MainWindow::keepPrefetched(std::shared_ptr<const PipelineResult> result) {
  const Prefetched p = prefetched_;
  recent_.keep(p.key, result);
  // Its figures were drawn on the worker thread with it: Page Down shows them at once.
  figures_->keep(p.key, result->figures);
  prefetchNextStep();  // the reader may have moved on meanwhile: the step next to where the reader is now
}

}  // namespace rt::app
