#include "app/computation_runner.h"

#include <QMetaObject>
#include <QThread>

#include "core/vector_state.h"

namespace rt::app {

// Forwards progress to the GUI thread (queued) at most once per percent, and can be cancelled from it.
class CancellableProgress : public CallbackProgress {
 public:
  explicit CancellableProgress(ComputationRunner* runner)
      : CallbackProgress([this](double fraction, const std::string& stage) { forward(fraction, stage); }),
        runner_(runner) {}

 private:
  void forward(double fraction, const std::string& stage) {
    const int percent = static_cast<int>(fraction * 100);
    if (percent == lastPercent_ && stage == lastStage_) return;
    lastPercent_ = percent;
    lastStage_ = stage;
    const QString label = QString::fromStdString(stage);
    QMetaObject::invokeMethod(
        runner_, [runner = runner_, fraction, label] { emit runner->progress(fraction, label); },
        Qt::QueuedConnection);
  }
  ComputationRunner* runner_;
  int lastPercent_ = -1;
  std::string lastStage_;
};

ComputationRunner::ComputationRunner(QObject* parent) : QObject(parent) {
  qRegisterMetaType<std::shared_ptr<const rt::app::PipelineResult>>();
}

ComputationRunner::~ComputationRunner() {
  queued_.reset();
  if (thread_) {
    cancel();
    thread_->wait();
    delete thread_;
    thread_ = nullptr;
  }
}

void ComputationRunner::start(Job job) {
  if (thread_) {
    queued_ = std::move(job);
    cancel();
    return;
  }
  launch(std::move(job));
}

void ComputationRunner::runNow(const Job& job) {
  if (thread_) {
    queued_.reset();
    discard_ = true;
    cancel();
  }
  runBlocking(job);
}

void ComputationRunner::cancel() {
  if (currentProgress_) currentProgress_->cancel();
}

void ComputationRunner::launch(Job job) {
  currentProgress_ = std::make_shared<CancellableProgress>(this);
  outcome_.reset();
  error_.clear();
  wasCancelled_ = false;
  discard_ = false;
  auto progress = currentProgress_;
  thread_ = QThread::create([this, job = std::move(job), progress] {
    clearUpperVectorState();  // the GUI thread's libraries may have left it dirty (core/vector_state.h)
    try {
      outcome_ = std::make_shared<PipelineResult>(job(*progress));
    } catch (const Cancelled&) {
      wasCancelled_ = true;
    } catch (const InputError& e) {
      error_ = QString::fromStdString(e.what());
    } catch (const std::exception& e) {
      error_ = QString::fromStdString(e.what());
    }
  });
  connect(thread_, &QThread::finished, this, &ComputationRunner::onThreadDone);
  emit busyChanged(true);
  thread_->start();
}

void ComputationRunner::onThreadDone() {
  thread_->deleteLater();
  thread_ = nullptr;
  currentProgress_.reset();
  if (queued_) {
    Job next = std::move(*queued_);
    queued_.reset();
    launch(std::move(next));
    return;
  }
  emit busyChanged(false);
  if (discard_) {
    discard_ = false;
    outcome_.reset();
    return;
  }
  if (wasCancelled_)
    emit cancelled();
  else if (!error_.isEmpty())
    emit failed(error_);
  else if (outcome_)
    emit finished(std::move(outcome_));
}

void ComputationRunner::runBlocking(const Job& job) {
  clearUpperVectorState();  // on the GUI thread, whose libraries may have left it dirty (core/vector_state.h)
  try {
    auto result = std::make_shared<PipelineResult>(job(noProgress()));
    emit finished(std::move(result));
  } catch (const Cancelled&) {
    emit cancelled();
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(e.what()));
  }
}

}  // namespace rt::app
