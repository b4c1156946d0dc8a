#include "app/vtk_widget.h"

#include "app/render_lock.h"

#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLState.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSurfaceFormat>
#include <QWheelEvent>

#include <cmath>

// GL enums without pulling in a GL header next to Qt's (both define them identically).
#ifndef GL_DRAW_FRAMEBUFFER
#define GL_DRAW_FRAMEBUFFER 0x8CA9
#endif
#ifndef GL_COLOR_BUFFER_BIT
#define GL_COLOR_BUFFER_BIT 0x00004000
#endif
#ifndef GL_NEAREST
#define GL_NEAREST 0x2600
#endif
#ifndef GL_LEQUAL
#define GL_LEQUAL 0x0203
#endif

namespace rt::app {

void VtkWidget::setDefaultSurfaceFormat() {
  // What vtkOpenGLRenderWindow asks for: a 3.2 core profile with depth, no multisampling (VTK does its own
  // FXAA).
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
  format.setRedBufferSize(8);
  format.setGreenBufferSize(8);
  format.setBlueBufferSize(8);
  format.setDepthBufferSize(24);
  format.setAlphaBufferSize(8);
  format.setStencilBufferSize(0);
  format.setSamples(0);
  QSurfaceFormat::setDefaultFormat(format);
}

VtkWidget::VtkWidget(QWidget* parent) : QOpenGLWidget(parent) {
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(false);
  setMinimumSize(160, 120);

  renderWindow_ = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  // No multisampling (VTK asks for 4 samples by default): in a software renderer it costs a third of
  // every frame; the scene view smooths its edges with FXAA instead, as the exported figures do.
  renderWindow_->SetMultiSamples(0);
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  renderWindow_->AddRenderer(renderer_);
  // Nothing may render until Qt has created the GL context (initializeGL).
  renderWindow_->SetReadyForRendering(false);

  interactor_ = vtkSmartPointer<vtkGenericRenderWindowInteractor>::New();
  interactor_->SetRenderWindow(renderWindow_);
  auto style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
  interactor_->SetInteractorStyle(style);
  interactor_->Initialize();
  // The interactor never renders itself: its style asks for a frame (RenderEvent) at every step of a drag,
  // and rendering it there, outside paintGL, would be followed by the render of the paint it triggers. A
  // paint is requested instead, which renders once (Qt merges the requests of a burst of mouse moves).
  interactor_->EnableRenderOff();
  interactorObserver_ = interactor_->AddObserver(vtkCommand::RenderEvent, this, &VtkWidget::requestRender);

  observerTags_[0] =
      renderWindow_->AddObserver(vtkCommand::WindowMakeCurrentEvent, this, &VtkWidget::onRenderWindowEvent);
  observerTags_[1] =
      renderWindow_->AddObserver(vtkCommand::WindowIsCurrentEvent, this, &VtkWidget::onRenderWindowEvent);
  observerTags_[2] =
      renderWindow_->AddObserver(vtkCommand::WindowFrameEvent, this, &VtkWidget::onRenderWindowEvent);
}

VtkWidget::~VtkWidget() {
  // Release VTK's GL objects while Qt's context still exists.
  if (context()) {
    QOpenGLWidget::makeCurrent();
    releaseGraphicsResources();
    doneCurrent();
  }
  for (unsigned long tag : observerTags_) renderWindow_->RemoveObserver(tag);
  interactor_->RemoveObserver(interactorObserver_);
}

vtkGenericOpenGLRenderWindow* VtkWidget::renderWindow() const {
  return renderWindow_;
}
vtkGenericRenderWindowInteractor* VtkWidget::interactor() const {
  return interactor_;
}
vtkRenderer* VtkWidget::renderer() const {
  return renderer_;
}

void VtkWidget::requestRender() {
  renderPending_ = true;
  update();
}

void VtkWidget::onRenderWindowEvent(vtkObject*, unsigned long eventId, void* callData) {
  switch (eventId) {
    case vtkCommand::WindowMakeCurrentEvent:
      // The QOpenGLContext call, not QOpenGLWidget::makeCurrent(): the latter re-binds Qt's FBO behind VTK's
      // GL state cache, after which VTK attaches its own textures to Qt's framebuffer and renders garbage.
      if (context() && QOpenGLContext::currentContext() != context())
        context()->makeCurrent(context()->surface());
      break;
    case vtkCommand::WindowIsCurrentEvent: {
      bool& isCurrent = *static_cast<bool*>(callData);
      isCurrent = context() != nullptr && QOpenGLContext::currentContext() == context();
      break;
    }
    case vtkCommand::WindowFrameEvent:
      // VTK finished a frame outside paintGL (e.g. the interactor style rotating the camera): show it.
      if (!inPaint_) update();
      break;
    default:
      break;
  }
}

void VtkWidget::initializeGL() {
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &VtkWidget::releaseGraphicsResources,
          Qt::DirectConnection);
  renderWindow_->SetOwnContext(0);
  // VTK renders into its own offscreen framebuffer; paintGL blits that into Qt's framebuffer object.
  renderWindow_->SetFrameBlitModeToNoBlit();
  renderWindow_->SetReadyForRendering(true);
  renderWindow_->InitializeFromCurrentContext();
  renderWindow_->SetForceMaximumHardwareLineWidth(1);
  const double ratio = devicePixelRatioF();
  const int w = static_cast<int>(std::lround(width() * ratio));
  const int h = static_cast<int>(std::lround(height() * ratio));
  renderWindow_->SetSize(w, h);
  interactor_->UpdateSize(w, h);
  initialized_ = true;
  renderPending_ = true;
}

void VtkWidget::resizeGL(int width, int height) {
  const double ratio = devicePixelRatioF();
  const int w = static_cast<int>(std::lround(width * ratio));
  const int h = static_cast<int>(std::lround(height * ratio));
  renderWindow_->SetSize(w, h);
  interactor_->UpdateSize(w, h);
  renderPending_ = true;
}

void VtkWidget::paintGL() {
  if (!initialized_) return;
  inPaint_ = true;
  vtkOpenGLState* state = renderWindow_->GetState();
  const int w = renderWindow_->GetSize()[0];
  const int h = renderWindow_->GetSize()[1];
  // Qt changed GL state behind VTK's cache since the last frame: start from what is really bound.
  state->Reset();
  state->Push();
  state->vtkglDepthFunc(GL_LEQUAL);  // Qt leaves GL_LESS; VTK expects GL_LEQUAL
  // VTK draws into a framebuffer of its own, which Qt never discards: a paint that Qt asks for (an expose,
  // a grab) copies the last frame again, and only a changed scene is rendered, a frame at a million elements
  // costing a good part of a second in a software renderer.
  if (renderPending_) {
    const std::lock_guard lock(renderMutex());
    renderWindow_->Render();
  }
  renderPending_ = false;
  state->Pop();

  // Copy VTK's display framebuffer into this widget's framebuffer object (not 0 in a QOpenGLWidget).
  state->PushDrawFramebufferBinding();
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  state->vtkglViewport(0, 0, w, h);
  state->vtkglScissor(0, 0, w, h);
  renderWindow_->BlitDisplayFramebuffer(0, 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  // Qt composes the widget with its alpha: force it opaque, whatever VTK left there.
  state->vtkglColorMask(false, false, false, true);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  state->vtkglColorMask(true, true, true, true);
  state->PopDrawFramebufferBinding();
  inPaint_ = false;
}

void VtkWidget::releaseGraphicsResources() {
  if (!initialized_) return;
  initialized_ = false;
  renderWindow_->Finalize();
  renderWindow_->SetReadyForRendering(false);
}

void VtkWidget::forwardMouse(QMouseEvent* event, unsigned long vtkEvent) {
  const double ratio = devicePixelRatioF();
  const QPointF p = event->position() * ratio;
  const Qt::KeyboardModifiers mods = event->modifiers();
  interactor_->SetEventInformationFlipY(
      static_cast<int>(p.x()), static_cast<int>(p.y()), (mods & Qt::ControlModifier) ? 1 : 0,
      (mods & Qt::ShiftModifier) ? 1 : 0, 0, event->type() == QEvent::MouseButtonDblClick ? 1 : 0);
  interactor_->SetAltKey((mods & Qt::AltModifier) ? 1 : 0);
  interactor_->InvokeEvent(vtkEvent, event);
}

namespace {
unsigned long pressEventFor(Qt::MouseButton button) {
  switch (button) {
    case Qt::LeftButton:
      return vtkCommand::LeftButtonPressEvent;
    case Qt::RightButton:
      return vtkCommand::RightButtonPressEvent;
    case Qt::MiddleButton:
      return vtkCommand::MiddleButtonPressEvent;
    default:
      return vtkCommand::NoEvent;
  }
}
unsigned long releaseEventFor(Qt::MouseButton button) {
  switch (button) {
    case Qt::LeftButton:
      return vtkCommand::LeftButtonReleaseEvent;
    case Qt::RightButton:
      return vtkCommand::RightButtonReleaseEvent;
    case Qt::MiddleButton:
      return vtkCommand::MiddleButtonReleaseEvent;
    default:
      return vtkCommand::NoEvent;
  }
}
}  // namespace

void VtkWidget::mousePressEvent(QMouseEvent* event) {
  pressPosition_ = event->position().toPoint();
  interacting_ = true;
  if (const unsigned long id = pressEventFor(event->button()); id != vtkCommand::NoEvent)
    forwardMouse(event, id);
  event->accept();
}

void VtkWidget::mouseMoveEvent(QMouseEvent* event) {
  forwardMouse(event, vtkCommand::MouseMoveEvent);
  if (interacting_ && event->buttons() != Qt::NoButton) emit cameraInteraction();
  event->accept();
}

void VtkWidget::mouseReleaseEvent(QMouseEvent* event) {
  if (const unsigned long id = releaseEventFor(event->button()); id != vtkCommand::NoEvent)
    forwardMouse(event, id);
  interacting_ = false;
  // A click is a press and release within a few pixels: it selects instead of rotating.
  if (event->button() == Qt::LeftButton &&
      (event->position().toPoint() - pressPosition_).manhattanLength() <= 3)
    emit clicked(event->position().toPoint());
  else
    emit cameraInteraction();
  event->accept();
}

void VtkWidget::mouseDoubleClickEvent(QMouseEvent* event) {
  if (const unsigned long id = pressEventFor(event->button()); id != vtkCommand::NoEvent)
    forwardMouse(event, id);
  event->accept();
}

void VtkWidget::wheelEvent(QWheelEvent* event) {
  const double ratio = devicePixelRatioF();
  const QPointF p = event->position() * ratio;
  interactor_->SetEventInformationFlipY(static_cast<int>(p.x()), static_cast<int>(p.y()),
                                        (event->modifiers() & Qt::ControlModifier) ? 1 : 0,
                                        (event->modifiers() & Qt::ShiftModifier) ? 1 : 0);
  const int delta = event->angleDelta().y();
  if (delta > 0)
    interactor_->InvokeEvent(vtkCommand::MouseWheelForwardEvent, event);
  else if (delta < 0)
    interactor_->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, event);
  emit cameraInteraction();
  event->accept();
}

void VtkWidget::enterEvent(QEnterEvent* event) {
  interactor_->InvokeEvent(vtkCommand::EnterEvent, event);
  QOpenGLWidget::enterEvent(event);
}

void VtkWidget::leaveEvent(QEvent* event) {
  interactor_->InvokeEvent(vtkCommand::LeaveEvent, event);
  QOpenGLWidget::leaveEvent(event);
}

}  // namespace rt::app
