// The walkthrough of a step with a camera path: one solve, seen from every camera of the path in turn. The
// radiosity solution does not depend on the view, so flying through it costs only the drawing. A Walkthrough
// button starts and stops the flight; the window moves the 3D view's camera on cameraChanged.
#pragma once

#include <QWidget>
#include <vector>

#include "core/scene.h"

class QLabel;
class QPushButton;
class QTimer;

namespace rt::app {

class CameraPathPlayer : public QWidget {
  Q_OBJECT
 public:
  explicit CameraPathPlayer(QWidget* parent = nullptr);

  // The frames of the step's path (empty: hidden). Stops a flight under way.
  void setPath(std::vector<Camera> frames);
  int frameCount() const { return static_cast<int>(frames_.size()); }
  int current() const { return current_; }
  bool playing() const;
  QPushButton* button() const { return button_; }
  void setFramesPerSecond(int fps);

 public slots:
  void play();
  void stop();
  void toggle();

 signals:
  void cameraChanged(const rt::Camera& camera);

 private:
  void advance();
  void updateLabel();

  std::vector<Camera> frames_;
  int current_ = 0;
  QPushButton* button_ = nullptr;
  QLabel* label_ = nullptr;
  QTimer* timer_ = nullptr;
};

}  // namespace rt::app
