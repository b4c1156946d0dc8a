#include "app/camera_path_player.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTimer>

namespace rt::app {

CameraPathPlayer::CameraPathPlayer(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  button_ = new QPushButton(tr("Walkthrough"), this);
  button_->setObjectName("walkthroughButton");
  button_->setToolTip(
      tr("Fly through the step's camera path: the solution is computed once and seen from every camera"));
  label_ = new QLabel(this);
  layout->addWidget(button_);
  layout->addWidget(label_, 1);
  timer_ = new QTimer(this);
  setFramesPerSecond(24);
  connect(button_, &QPushButton::clicked, this, &CameraPathPlayer::toggle);
  connect(timer_, &QTimer::timeout, this, &CameraPathPlayer::advance);
  setVisible(false);
}

void CameraPathPlayer::setFramesPerSecond(int fps) {
  timer_->setInterval(1000 / std::max(1, fps));
}

void CameraPathPlayer::setPath(std::vector<Camera> frames) {
  stop();
  frames_ = std::move(frames);
  current_ = 0;
  setVisible(!frames_.empty());
  updateLabel();
}

bool CameraPathPlayer::playing() const {
  return timer_->isActive();
}

void CameraPathPlayer::play() {
  if (frames_.empty()) return;
  // From the start, whether the last flight ended or was stopped half-way.
  current_ = 0;
  emit cameraChanged(frames_.front());
  button_->setText(tr("Stop"));
  timer_->start();
  updateLabel();
}

void CameraPathPlayer::stop() {
  timer_->stop();
  button_->setText(tr("Walkthrough"));
}

void CameraPathPlayer::toggle() {
  playing() ? stop() : play();
}

void CameraPathPlayer::advance() {
  if (current_ + 1 >= frameCount()) {
    stop();
    return;
  }
  ++current_;
  emit cameraChanged(frames_[static_cast<std::size_t>(current_)]);
  updateLabel();
}

void CameraPathPlayer::updateLabel() {
  label_->setText(frames_.empty() ? QString()
                                  : tr("camera path: frame %1 / %2").arg(current_ + 1).arg(frameCount()));
}

}  // namespace rt::app
