// Replaying a solver's recorded iterations: play/pause, speed, a slider over the iterations and a
// next-iteration button. It only keeps the clock; the window maps the iteration to the history's B (and the
// compare pane uses the same clock).
#pragma once

#include <QWidget>
#include <vector>

class QLabel;
class QToolButton;
class QSlider;
class QSpinBox;
class QTimer;

namespace rt::app {

class IterationPlayer : public QWidget {
  Q_OBJECT
 public:
  explicit IterationPlayer(QWidget* parent = nullptr);

  // Number of recorded iterations (0 hides the controls' meaning: everything disabled). Jumps to the last
  // one.
  void setIterationCount(int count);
  // The same, with what each record stands for: record k is after numbers[k] of `unit` (wording's
  // iterationUnit: a bounces run's record 0 is the emission, after 0 bounces). The label reads
  // "3 / 3 bounces", as the status line's "after 3 bounces".
  void setIterations(std::vector<int> numbers, const QString& unit);
  QString label() const;
  int iterationCount() const { return count_; }
  int current() const { return current_; }
  bool playing() const;
  void setSpeed(int iterationsPerSecond);

 public slots:
  void setCurrent(int index);
  void play();
  void pause();
  void togglePlay();
  void next();
  void previous();

 signals:
  // 0-based index into the history.
  void currentChanged(int index);

 private:
  void updateLabels();

  int count_ = 0;
  int current_ = 0;
  std::vector<int> numbers_;  // the count each record stands for
  QString unit_;
  QToolButton* playButton_ = nullptr;
  QToolButton* nextButton_ = nullptr;
  QToolButton* firstButton_ = nullptr;
  QSlider* slider_ = nullptr;
  QSpinBox* speed_ = nullptr;
  QLabel* label_ = nullptr;
  QTimer* timer_ = nullptr;
};

}  // namespace rt::app
