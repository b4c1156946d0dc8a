#include "app/scene_view.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkIntArray.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

namespace rt::app {

SceneView::SceneView(QWidget* parent) : VtkWidget(parent) {
  renderer()->SetBackground(0.12, 0.12, 0.14);
  mapper_ = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper_->SetScalarModeToUseCellData();
  mapper_->SetColorModeToDirectScalars();
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper_);
  // Radiosity is the colour: no lighting on top of it.
  actor_->GetProperty()->SetLighting(false);
  actor_->GetProperty()->SetEdgeColor(0.2, 0.2, 0.2);
  actor_->VisibilityOff();
  renderer()->AddActor(actor_);

  highlightActor_ = vtkSmartPointer<vtkActor>::New();
  highlightActor_->GetProperty()->SetRepresentationToWireframe();
  highlightActor_->GetProperty()->SetColor(1.0, 0.85, 0.0);
  highlightActor_->GetProperty()->SetLineWidth(4.0);
  highlightActor_->GetProperty()->SetLighting(false);
  highlightActor_->VisibilityOff();
  renderer()->AddActor(highlightActor_);

  caption_ = vtkSmartPointer<vtkTextActor>::New();
  caption_->GetTextProperty()->SetFontSize(18);
  caption_->GetTextProperty()->SetColor(0.95, 0.95, 0.95);
  caption_->SetDisplayPosition(10, 10);
  renderer()->AddActor2D(caption_);

  connect(this, &VtkWidget::clicked, this, [this](QPoint p) {
    const int element = pickElement(p);
    if (element >= 0) emit elementPicked(element);
  });
}

SceneView::~SceneView() = default;

void SceneView::setMesh(const Mesh* mesh, const Camera& camera, bool resetCamera) {
  mesh_ = mesh;
  highlighted_.clear();
  if (!mesh_) {
    actor_->VisibilityOff();
    highlightActor_->VisibilityOff();
    requestRender();
    return;
  }
  if (B_.rows() != static_cast<Eigen::Index>(mesh_->size())) B_ = mesh_->emission;
  polyData_ = makeRadiosityPolyData(*mesh_, B_, display_);
  mapper_->SetInputData(polyData_);
  actor_->VisibilityOn();
  rebuildHighlight();
  if (resetCamera) applyCamera(camera);
  requestRender();
}

void SceneView::applyCamera(const Camera& c) {
  vtkCamera* camera = renderer()->GetActiveCamera();
  camera->SetPosition(c.position.data());
  camera->SetFocalPoint(c.target.data());
  camera->SetViewUp(c.up.data());
  camera->SetViewAngle(c.fovYDegrees);
  renderer()->ResetCameraClippingRange();
  requestRender();
}

void SceneView::setRadiosity(const RgbField& B) {
  B_ = B;
  if (!mesh_ || B.rows() != static_cast<Eigen::Index>(mesh_->size())) return;
  polyData_ = makeRadiosityPolyData(*mesh_, B_, display_);
  mapper_->SetInputData(polyData_);
  requestRender();
}

void SceneView::setDisplayOptions(const DisplayOptions& options) {
  display_ = options;
  if (mesh_) setRadiosity(B_);
}

void SceneView::setShowEdges(bool show) {
  showEdges_ = show;
  actor_->GetProperty()->SetEdgeVisibility(show);
  requestRender();
}

void SceneView::setCaption(const QString& text) {
  caption_->SetInput(text.toUtf8().constData());
  requestRender();
}

void SceneView::setHighlighted(const std::vector<int>& elements) {
  highlighted_ = elements;
  rebuildHighlight();
  requestRender();
}

void SceneView::rebuildHighlight() {
  if (!mesh_ || highlighted_.empty() || !polyData_) {
    highlightActor_->VisibilityOff();
    return;
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (int e : highlighted_) {
    if (e < 0 || e >= static_cast<int>(mesh_->size())) continue;
    const auto& vertices = mesh_->elements[e].vertices;
    std::vector<vtkIdType> ids(vertices.begin(), vertices.end());
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  auto outline = vtkSmartPointer<vtkPolyData>::New();
  outline->SetPoints(polyData_->GetPoints());
  outline->SetPolys(cells);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(outline);
  mapper->ScalarVisibilityOff();
  // Drawn over the surfaces so the outline is not half hidden by the depth test.
  mapper->SetResolveCoincidentTopologyToPolygonOffset();
  mapper->SetRelativeCoincidentTopologyLineOffsetParameters(0, -66000);
  highlightActor_->SetMapper(mapper);
  highlightActor_->VisibilityOn();
}

void SceneView::syncCameraFrom(const SceneView& other) {
  renderer()->GetActiveCamera()->DeepCopy(other.renderer()->GetActiveCamera());
  renderer()->ResetCameraClippingRange();
  requestRender();
}

int SceneView::pickElement(QPoint position) {
  if (!mesh_ || !polyData_) return -1;
  auto picker = vtkSmartPointer<vtkCellPicker>::New();
  picker->SetTolerance(0.0005);
  const double ratio = devicePixelRatioF();
  const double x = position.x() * ratio;
  const double y = (height() - 1 - position.y()) * ratio;
  if (!picker->Pick(x, y, 0, renderer())) return -1;
  if (picker->GetActor() != actor_.Get()) return -1;
  const vtkIdType cell = picker->GetCellId();
  auto* ids = vtkIntArray::SafeDownCast(polyData_->GetCellData()->GetArray("ElementId"));
  if (cell < 0 || !ids || cell >= ids->GetNumberOfTuples()) return -1;
  return ids->GetValue(cell);
}

}  // namespace rt::app
