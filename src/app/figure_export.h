// Writing every figure of a lesson at once ("Export all figures"), without freezing the window. Each step is
// computed on a worker thread (form factors, solves, refinements: the expensive part); its figures are then
// drawn on the GUI thread, one step at a time, because the viz layer's offscreen VTK windows talk to the X
// server the GUI thread owns. Progress covers the whole lesson; cancel stops at the next progress check of
// the step being computed and writes nothing more (the files already written stay).
#pragma once

#include <QObject>
#include <QSize>
#include <QString>
#include <memory>

#include "lesson/step_result.h"

class QThread;

namespace rt::app {

class LessonLibrary;
class ForwardingProgress;

class LessonFigureExport : public QObject {
  Q_OBJECT
 public:
  // `library` must outlive the export (the window owns both and deletes the export first).
  LessonFigureExport(LessonLibrary& library, int lessonIndex, QString folder, QSize size,
                     QObject* parent = nullptr);
  ~LessonFigureExport() override;  // cancels and waits for the worker

  void start();
  void cancel();
  bool running() const { return thread_ != nullptr; }
  int written() const { return written_; }
  const QString& folder() const { return folder_; }

 signals:
  void progress(double fraction, const QString& stage);
  void finished(int written);
  void failed(const QString& message);
  void cancelled();

 private:
  void drawStep(int step, const std::shared_ptr<const lesson::StepResult>& stepResult);
  void onWorkerDone();

  LessonLibrary& library_;
  int lesson_;
  QString folder_;
  QSize size_;
  QThread* thread_ = nullptr;
  std::shared_ptr<ForwardingProgress> progress_;
  int written_ = 0;
  QString error_;      // the first failure, from either thread (read after the worker ended)
  QString drawError_;  // a drawing failure on the GUI thread
  bool cancelledByUser_ = false;
};

}  // namespace rt::app
