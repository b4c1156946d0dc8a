// What the reader sees while something long runs (form factors, a solve, a refinement, writing a lesson's
// figures): a labelled progress bar and a Cancel button at the bottom of the window. It lives in the status
// bar, where a progress indicator is expected and where it never covers the 3D view; in presenter mode, whose
// status bar is hidden, the window shows the status bar only while a job runs, so the class still sees it.
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace rt::app {

class ProgressStrip : public QWidget {
  Q_OBJECT
 public:
  explicit ProgressStrip(QWidget* parent = nullptr);

  // A job that ends sooner is not worth a flash of a progress bar.
  static constexpr int kShowDelayMs = 500;

  // Starts a job called `what` (e.g. "Computing", "Writing the figures") at 0 %; the strip appears when it
  // is still running kShowDelayMs later.
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
  void appeared();  // the strip became visible (the window then shows its status bar in presenter mode)

 private:
  QString what_;
  QLabel* label_ = nullptr;
  QProgressBar* bar_ = nullptr;
  QPushButton* cancel_ = nullptr;
  bool active_ = false;
  QString stage_;
  QElapsedTimer stageTimer_;
  QTimer showTimer_;
};

}  // namespace rt::app
