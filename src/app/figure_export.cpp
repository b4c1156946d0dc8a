#include "app/figure_export.h"

#include <QDir>
#include <QMetaObject>
#include <QThread>
#include <filesystem>

#include "app/lesson_session.h"
#include "app/render_lock.h"
#include "core/input_error.h"
#include "core/progress.h"
#include "core/vector_state.h"
#include "lesson/step_result.h"
#include "viz/lesson_figures.h"

namespace rt::app {

// Progress of the whole lesson from the progress of one step: step s of n covers [s/n, (s+1)/n]. Forwarded
// to the GUI thread (queued) at most once per per-mille and stage; cancellable from the GUI thread.
class ForwardingProgress : public CallbackProgress {
 public:
  ForwardingProgress(LessonFigureExport* target, int steps)
      : CallbackProgress([this](double f, const std::string& stage) { forward(f, stage); }),
        target_(target),
        steps_(std::max(1, steps)) {}
  void setStep(int step, const QString& label) {
    step_ = step;
    label_ = label;
    forward(0.0, {});
  }

 private:
  void forward(double fraction, const std::string& stage) {
    const double whole = (step_ + std::clamp(fraction, 0.0, 1.0)) / steps_;
    const int permille = static_cast<int>(whole * 1000);
    if (permille == lastPermille_ && stage == lastStage_) return;
    lastPermille_ = permille;
    lastStage_ = stage;
    const QString text = stage.empty() ? label_ : label_ + ": " + QString::fromStdString(stage);
    QMetaObject::invokeMethod(
        target_, [target = target_, whole, text] { emit target->progress(whole, text); },
        Qt::QueuedConnection);
  }
  LessonFigureExport* target_;
  int steps_;
  int step_ = 0;
  QString label_;
  int lastPermille_ = -1;
  std::string lastStage_;
};

LessonFigureExport::LessonFigureExport(LessonLibrary& library, int lessonIndex, QString folder, QSize size,
                                       QObject* parent)
    : QObject(parent), library_(library), lesson_(lessonIndex), folder_(std::move(folder)), size_(size) {}

LessonFigureExport::~LessonFigureExport() {
  if (thread_) {
    cancel();
    thread_->wait();
    delete thread_;
  }
}

void LessonFigureExport::start() {
  if (thread_) return;
  const lesson::Lesson& lesson = library_.lessons().at(static_cast<std::size_t>(lesson_));
  const int steps = static_cast<int>(lesson.steps.size());
  progress_ = std::make_shared<ForwardingProgress>(this, steps);
  written_ = 0;
  error_.clear();
  drawError_.clear();
  cancelledByUser_ = false;
  std::error_code ignored;
  std::filesystem::create_directories(folder_.toStdString(), ignored);
  auto progress = progress_;
  thread_ = QThread::create([this, progress, steps] {
    clearUpperVectorState();  // the GUI thread's libraries may have left it dirty (core/vector_state.h)
    const lesson::Lesson& lesson = library_.lessons().at(static_cast<std::size_t>(lesson_));
    try {
      for (int s = 0; s < steps; ++s) {
        if (progress->cancelled()) throw Cancelled();
        const lesson::Step& step = lesson.steps[static_cast<std::size_t>(s)];
        progress->setStep(s, tr("Step %1 of %2").arg(s + 1).arg(steps));
        if (step.stage == lesson::Stage::Text || step.figureFiles().empty()) continue;
        std::shared_ptr<const lesson::StepResult> result = library_.computeStep(lesson_, s, *progress);
        // Drawn on the GUI thread; queued events keep their order, so every step is drawn before the
        // worker's end is handled.
        QMetaObject::invokeMethod(
            this, [this, s, result] { drawStep(s, result); }, Qt::QueuedConnection);
      }
    } catch (const Cancelled&) {
      cancelledByUser_ = true;
    } catch (const std::exception& e) {
      error_ = QString::fromStdString(e.what());
    }
  });
  connect(thread_, &QThread::finished, this, &LessonFigureExport::onWorkerDone);
  thread_->start();
}

void LessonFigureExport::cancel() {
  if (progress_) progress_->cancel();
}

void LessonFigureExport::drawStep(int s, const std::shared_ptr<const lesson::StepResult>& result) {
  if ((progress_ && progress_->cancelled()) || !drawError_.isEmpty()) return;
  const lesson::Lesson& lesson = library_.lessons().at(static_cast<std::size_t>(lesson_));
  const lesson::Step& step = lesson.steps.at(static_cast<std::size_t>(s));
  viz::StepFigureSettings settings;
  settings.width = size_.width();
  settings.height = size_.height();
  try {
    const std::lock_guard lock(renderMutex());
    written_ += static_cast<int>(
        viz::renderStepFigures(lesson, step, *result, folder_.toStdString(), settings).size());
  } catch (const std::exception& e) {
    drawError_ = tr("step %1: %2").arg(s + 1).arg(e.what());
    cancel();  // nothing more to compute
  }
}

void LessonFigureExport::onWorkerDone() {
  thread_->deleteLater();
  thread_ = nullptr;
  progress_.reset();
  if (!drawError_.isEmpty())
    emit failed(drawError_);
  else if (!error_.isEmpty())
    emit failed(error_);
  else if (cancelledByUser_)
    emit cancelled();
  else
    emit finished(written_);
}

}  // namespace rt::app
