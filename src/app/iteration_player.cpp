#include "app/iteration_player.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>
#include <QToolButton>

#include "app/wording.h"

namespace rt::app {

IterationPlayer::IterationPlayer(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 2, 4, 2);
  // Tool buttons are as wide as their text: push buttons' 80-pixel minimum made the player alone wider than
  // half a projector's screen.
  auto button = [this](const QString& text) {
    auto* b = new QToolButton(this);
    b->setText(text);
    return b;
  };
  firstButton_ = button(tr("|<"));
  firstButton_->setToolTip(tr("First iteration"));
  playButton_ = button(tr("Play"));
  playButton_->setToolTip(tr("Play / pause the iterations (Space)"));
  nextButton_ = button(tr("Next"));
  nextButton_->setToolTip(tr("Next iteration (N)"));
  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setObjectName("iterationSlider");
  slider_->setMinimumWidth(80);
  speed_ = new QSpinBox(this);
  speed_->setRange(1, 120);
  speed_->setValue(8);
  speed_->setSuffix(tr(" it/s"));
  speed_->setToolTip(tr("Replay speed"));
  label_ = new QLabel(this);
  label_->setMinimumWidth(90);
  layout->addWidget(firstButton_);
  layout->addWidget(playButton_);
  layout->addWidget(nextButton_);
  layout->addWidget(slider_, 1);
  layout->addWidget(label_);
  layout->addWidget(speed_);

  timer_ = new QTimer(this);
  connect(timer_, &QTimer::timeout, this, [this] {
    if (current_ + 1 >= count_)
      pause();
    else
      setCurrent(current_ + 1);
  });
  connect(playButton_, &QToolButton::clicked, this, &IterationPlayer::togglePlay);
  connect(nextButton_, &QToolButton::clicked, this, &IterationPlayer::next);
  connect(firstButton_, &QToolButton::clicked, this, [this] { setCurrent(0); });
  connect(slider_, &QSlider::valueChanged, this, &IterationPlayer::setCurrent);
  connect(speed_, &QSpinBox::valueChanged, this,
          [this](int v) { timer_->setInterval(1000 / std::max(1, v)); });
  timer_->setInterval(1000 / speed_->value());
  setIterationCount(0);
}

void IterationPlayer::setIterationCount(int count) {
  std::vector<int> numbers(static_cast<std::size_t>(std::max(0, count)));
  for (std::size_t k = 0; k < numbers.size(); ++k) numbers[k] = static_cast<int>(k) + 1;
  setIterations(std::move(numbers), tr("iteration"));
}

void IterationPlayer::setIterations(std::vector<int> numbers, const QString& unit) {
  pause();
  numbers_ = std::move(numbers);
  unit_ = unit;
  count_ = static_cast<int>(numbers_.size());
  const QSignalBlocker block(slider_);
  slider_->setRange(0, std::max(0, count_ - 1));
  current_ = std::max(0, count_ - 1);
  slider_->setValue(current_);
  setEnabled(count_ > 0);
  updateLabels();
}

bool IterationPlayer::playing() const {
  return timer_->isActive();
}

void IterationPlayer::setSpeed(int iterationsPerSecond) {
  speed_->setValue(iterationsPerSecond);
}

void IterationPlayer::setCurrent(int index) {
  if (count_ == 0) return;
  index = std::clamp(index, 0, count_ - 1);
  if (index == current_ && slider_->value() == index) return;
  current_ = index;
  {
    const QSignalBlocker block(slider_);
    slider_->setValue(index);
  }
  updateLabels();
  emit currentChanged(index);
}

void IterationPlayer::play() {
  if (count_ <= 1) return;
  if (current_ + 1 >= count_) setCurrent(0);  // replay from the start
  timer_->start();
  updateLabels();
}

void IterationPlayer::pause() {
  timer_->stop();
  updateLabels();
}

void IterationPlayer::togglePlay() {
  playing() ? pause() : play();
}

void IterationPlayer::next() {
  setCurrent(current_ + 1);
}

void IterationPlayer::previous() {
  setCurrent(current_ - 1);
}

void IterationPlayer::updateLabels() {
  playButton_->setText(playing() ? tr("Pause") : tr("Play"));
  label_->setText(count_ > 0 ? tr("%1 / %2")
                                   .arg(numbers_[static_cast<std::size_t>(current_)])
                                   .arg(counted(numbers_.back(), unit_))
                             : tr("no iterations"));
}

QString IterationPlayer::label() const {
  return label_->text();
}

}  // namespace rt::app
