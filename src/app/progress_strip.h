// What the reader sees while something long runs (form factors, a solve, a refinement, writing a lesson's
// figures): a labelled progress bar and a Cancel button at the bottom of the window. It lives in the status
// bar, where a progress indicator is expected and where it never covers the 3D view; in presenter mode, whose
// status bar is hidden, the window shows the status bar only while a job runs, so the class still sees it.
#pragma once

#include <QElapsedTimer>
#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace rt::app {

class ProgressStrip : public QWidget {
  Q_OBJECT
 public:
  explicit ProgressStrip(QWidget* parent = nullptr);

  // Shows the strip for a job called `what` (e.g. "Computing", "Writing the figures"), at 0 %.
  void begin(const QString& what);
  // `fraction` in [0, 1] of the job; `stage` names the part running now (e.g. "form factors (hemicube)").
  void setProgress(double fraction, const QString& stage);
  // Hides the strip.
  void end();
  bool active() const { return active_; }
  // The bar's value in per mille and its text (tests, the status line); the label, with the time left once
  // it can be estimated ("Computing \u2014 about 3 min left").
  int value() const;
  QString text() const;
  QString label() const;
  QPushButton* cancelButton() const { return cancel_; }

 signals:
  void cancelRequested();

 private:
  QString what_;
  QLabel* label_ = nullptr;
  QProgressBar* bar_ = nullptr;
  QPushButton* cancel_ = nullptr;
  bool active_ = false;
  QString stage_;
  QElapsedTimer stageTimer_;
};

}  // namespace rt::app
