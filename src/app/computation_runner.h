// Runs the pipeline off the GUI thread, one computation at a time, with progress and cancellation. A
// cancelled or failed computation changes nothing: the previous result stays on screen. Starting a new
// computation while one runs cancels the running one and starts the new one when it has stopped.
#pragma once

#include <QObject>
#include <QString>
#include <functional>
#include <memory>
#include <optional>

#include "app/pipeline.h"

class QThread;

namespace rt::app {

class ComputationRunner : public QObject {
  Q_OBJECT
 public:
  explicit ComputationRunner(QObject* parent = nullptr);
  ~ComputationRunner() override;

  // A computation: everything it needs is captured by value, it reports to and polls the Progress it is
  // given.
  using Job = std::function<PipelineResult(Progress&)>;

  // Starts `job` on a worker thread (or queues it behind the running one, which is cancelled).
  void start(Job job);
  void cancel();
  bool busy() const { return thread_ != nullptr; }
  // Runs on the calling thread (screenshots, tests that need the result now). Emits the same signals.
  void runBlocking(const Job& job);
  // A quick job (an exercise, a page of text) that must not wait behind a long one: the running
  // computation is cancelled and its outcome dropped without a signal, and `job` runs now, blocking.
  void runNow(const Job& job);

 signals:
  void progress(double fraction, const QString& stage);
  void finished(std::shared_ptr<const rt::app::PipelineResult> result);
  void failed(const QString& message);
  void cancelled();
  void busyChanged(bool busy);

 private:
  void launch(Job job);
  void onThreadDone();

  QThread* thread_ = nullptr;
  std::shared_ptr<class CancellableProgress> currentProgress_;
  std::shared_ptr<PipelineResult> outcome_;
  QString error_;
  bool wasCancelled_ = false;
  bool discard_ = false;  // the running computation was overtaken by runNow(): its outcome is not shown
  std::optional<Job> queued_;
};

}  // namespace rt::app
