// SceneView's camera: placed by a step, read back for exports, shared in compare mode, and moved by the
// reader, during which a large mesh is drawn as its stand-in (stand_in_actor.h) and the full mesh again on
// the still frame.
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkRenderer.h>
#include <QTimer>
#include <QWheelEvent>

#include "app/scene_view.h"
#include "app/stand_in_actor.h"
#include "viz/mesh_edges.h"

namespace rt::app {

void SceneView::onCameraInteraction(vtkObject*, unsigned long event, void*) {
  dragging_ = event == vtkCommand::StartInteractionEvent;
  if (dragging_)
    beginMotion();
  else if (!settle_->isActive())  // a wheel step's motion lasts until the wheel rests
    endMotion();
}

void SceneView::beginMotion() {
  if (inMotion_) return;
  inMotion_ = true;
  // FXAA costs a third of a frame in a software renderer, and a moving view does not show its stairs.
  renderer()->UseFXAAOff();
  standIn_->show(*actor_);
  // The stand-in's triangles are not the elements: no edges on them.
  if (edges_) edges_->actor()->SetVisibility(actor_->GetVisibility());
}

void SceneView::endMotion() {
  settle_->stop();
  if (!inMotion_) return;
  inMotion_ = false;
  renderer()->UseFXAAOn();
  standIn_->hide(*actor_, mesh_ != nullptr);
  if (edges_) edges_->actor()->SetVisibility(actor_->GetVisibility());
  requestRender();
}

void SceneView::noteCameraMotion() {
  settle_->start();
  beginMotion();
}

void SceneView::wheelEvent(QWheelEvent* event) {
  // Started before the step, so that the style's EndInteractionEvent of the step leaves the motion on.
  settle_->start();
  VtkWidget::wheelEvent(event);
  beginMotion();
}

void SceneView::applyCamera(const Camera& c) {
  vtkCamera* camera = renderer()->GetActiveCamera();
  camera->SetPosition(c.position.data());
  camera->SetFocalPoint(c.target.data());
  camera->SetViewUp(c.up.data());
  camera->SetViewAngle(c.fovYDegrees);
  fitViewAngle();
  renderer()->ResetCameraClippingRange();
  requestRender();
}

Camera SceneView::currentCamera() const {
  vtkCamera* camera = renderer()->GetActiveCamera();
  Camera c;
  camera->GetPosition(c.position.data());
  camera->GetFocalPoint(c.target.data());
  camera->GetViewUp(c.up.data());
  c.fovYDegrees = camera->GetViewAngle();
  return c;
}

void SceneView::fitViewAngle() {
  // A step's camera frames the scene for a roughly square view, its angle measured along the height. A pane
  // narrower than it is tall (each of compare mode's two) would then show only the middle of the room: it
  // takes the same angle across its width instead, so the whole framing stays in view.
  if (width() <= 0 || height() <= 0) return;
  vtkCamera* camera = renderer()->GetActiveCamera();
  const bool narrow = width() < height();
  if (camera->GetUseHorizontalViewAngle() == narrow) return;
  camera->SetUseHorizontalViewAngle(narrow);
  requestRender();
}

void SceneView::syncCameraFrom(const SceneView& other) {
  // The follower of compare mode moves and rests with the view the reader moves.
  if (other.inMotion())
    noteCameraMotion();
  else if (!dragging_)
    endMotion();
  renderer()->GetActiveCamera()->DeepCopy(other.renderer()->GetActiveCamera());
  fitViewAngle();
  renderer()->ResetCameraClippingRange();
  requestRender();
}

}  // namespace rt::app
