// A QOpenGLWidget that hosts a VTK render window. Debian's VTK Qt module (QVTKOpenGLNativeWidget) is built
// against Qt5 and must never be loaded into this Qt6 process, so this widget does what VTK's own widget does
// internally: VTK renders into Qt's current GL context (vtkGenericOpenGLRenderWindow) and the result is
// blitted into the widget's framebuffer object. See docs/app.md and ../shared/docs/platform-notes.md for why
// each step is needed.
#pragma once

#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <QImage>
#include <QOpenGLWidget>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkRenderer;
class vtkObject;

namespace rt::app {

class VtkWidget : public QOpenGLWidget {
  Q_OBJECT
 public:
  explicit VtkWidget(QWidget* parent = nullptr);
  ~VtkWidget() override;

  // Must be called once before QApplication is constructed: VTK needs a 3.2 core profile context.
  static void setDefaultSurfaceFormat();

  vtkGenericOpenGLRenderWindow* renderWindow() const;
  vtkGenericRenderWindowInteractor* interactor() const;
  // The renderer showing the scene (created with the widget; callers add their props).
  vtkRenderer* renderer() const;

  // Schedules a repaint that re-renders the VTK scene.
  void requestRender();

 signals:
  // Left click without drag at widget pixel `position` (for picking).
  void clicked(QPoint position);
  // The camera moved through user interaction (compare mode mirrors it into another view).
  void cameraInteraction();

 protected:
  void initializeGL() override;
  void resizeGL(int width, int height) override;
  void paintGL() override;

  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void enterEvent(QEnterEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  void onRenderWindowEvent(vtkObject* caller, unsigned long eventId, void* callData);
  void releaseGraphicsResources();
  void forwardMouse(QMouseEvent* event, unsigned long vtkEvent);

  vtkSmartPointer<vtkGenericOpenGLRenderWindow> renderWindow_;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor_;
  vtkSmartPointer<vtkRenderer> renderer_;
  unsigned long observerTags_[3] = {0, 0, 0};
  unsigned long interactorObserver_ = 0;
  bool renderPending_ = true;
  bool initialized_ = false;
  bool inPaint_ = false;  // frames VTK finishes inside paintGL need no further update()
  QPoint pressPosition_;
  bool interacting_ = false;
};

}  // namespace rt::app
