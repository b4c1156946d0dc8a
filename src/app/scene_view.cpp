#include "app/scene_view.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkCommand.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkIntArray.h>
#include <vtkInteractorObserver.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkStaticCellLocator.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <QTimer>

#include <algorithm>
#include <cstring>

#include "app/stand_in_actor.h"
#include "viz/element_polydata.h"
#include "viz/mesh_edges.h"
#include "viz/vtk_geometry.h"
#include "viz/vtk_render.h"
#include "viz/vtk_views.h"

namespace rt::app {

SceneView::SceneView(QWidget* parent) : VtkWidget(parent) {
  renderer()->SetBackground(viz::kBackground[0], viz::kBackground[1], viz::kBackground[2]);
  // Edges smoothed by FXAA, as in the exported figures, except while the reader drags the camera: in a
  // software renderer it costs a third of a frame, and a moving view does not show its stairs.
  renderer()->UseFXAAOn();
  vtkInteractorObserver* style = interactor()->GetInteractorStyle();
  styleObservers_[0] =
      style->AddObserver(vtkCommand::StartInteractionEvent, this, &SceneView::onCameraInteraction);
  styleObservers_[1] =
      style->AddObserver(vtkCommand::EndInteractionEvent, this, &SceneView::onCameraInteraction);
  mapper_ = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper_->SetScalarModeToUsePointData();
  mapper_->SetColorModeToDirectScalars();
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper_);
  // Radiosity is the colour: no lighting on top of it.
  actor_->GetProperty()->SetLighting(false);
  actor_->GetProperty()->BackfaceCullingOn();
  actor_->GetProperty()->SetInterpolationToFlat();
  actor_->VisibilityOff();
  renderer()->AddActor(actor_);

  standIn_ = std::make_unique<StandInActor>(*renderer());
  settle_ = new QTimer(this);
  settle_->setSingleShot(true);
  settle_->setInterval(kSettleMilliseconds);
  connect(settle_, &QTimer::timeout, this, [this] {
    if (!dragging_) endMotion();
  });

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

SceneView::~SceneView() {
  for (unsigned long tag : styleObservers_) interactor()->GetInteractorStyle()->RemoveObserver(tag);
}

void SceneView::setMesh(const Mesh* mesh, const Camera& camera, bool resetCamera) {
  endMotion();  // a new mesh starts still, drawn in full
  mesh_ = mesh;
  highlighted_.clear();
  if (!mesh_) {
    // Nothing shown holds nothing: at a million elements the cells and colours are some 90 MB.
    smoothing_ = nullptr;
    picker_ = nullptr;
    polyData_ = nullptr;
    mapper_->SetInputData(nullptr);
    actor_->VisibilityOff();
    standIn_->rebuild(nullptr, {});
    highlightActor_->VisibilityOff();
    if (emitterOutline_) renderer()->RemoveActor(emitterOutline_);
    emitterOutline_ = nullptr;
    rebuildEdges();
    requestRender();
    return;
  }
  if (data_.B.rows() != static_cast<Eigen::Index>(mesh_->size())) data_.B = mesh_->emission;
  rebuildGeometry();
  actor_->VisibilityOn();
  rebuildHighlight();
  if (resetCamera) applyCamera(camera);
  requestRender();
}

void SceneView::setScene(const Mesh* mesh, const RgbField& B, const Camera& camera, bool resetCamera,
                         const RgbField& corners) {
  data_.B = B;
  data_.corners = corners;
  setMesh(mesh, camera, resetCamera);
}

void SceneView::setRadiosity(const RgbField& B) {
  data_.B = B;
  data_.corners.resize(0, 3);  // a replayed iteration holds element values
  if (!mesh_ || B.rows() != static_cast<Eigen::Index>(mesh_->size())) return;
  repaint3d();
  requestRender();
}

void SceneView::setViewOptions(const viz::SceneViewOptions& options) {
  options_ = options;
  applyLighting();
  actor_->GetProperty()->SetInterpolation(options_.image.smooth ? VTK_GOURAUD : VTK_FLAT);
  setShowEdges(options_.image.showEdges);
  if (mesh_) repaint3d();
  requestRender();
}

void SceneView::setMaterialView(bool materials) {
  materialView_ = materials;
  if (options_.colouring == viz::SceneColouring::Radiosity ||
      options_.colouring == viz::SceneColouring::Reflectance)
    options_.colouring = materials ? viz::SceneColouring::Reflectance : viz::SceneColouring::Radiosity;
  applyLighting();  // the colours follow with the next setScene or setMesh
}

void SceneView::applyLighting() {
  // The same mild headlight as the figure pipeline's material view (viz/vtk_views.cpp); radiosity and scalar
  // colourings are the colour itself.
  const bool shaded = options_.colouring == viz::SceneColouring::Reflectance;
  vtkProperty* property = actor_->GetProperty();
  property->SetLighting(shaded);
  property->SetAmbient(shaded ? 0.6 : 0.0);
  property->SetDiffuse(shaded ? 0.4 : 1.0);
  property->SetSpecular(0.0);
}

void SceneView::setScalarField(const Eigen::VectorXd& values, const std::string& title) {
  data_.scalar = values;
  options_.colouring = values.size() > 0 ? viz::SceneColouring::Scalar
                       : materialView_   ? viz::SceneColouring::Reflectance
                                         : viz::SceneColouring::Radiosity;
  applyLighting();
  options_.legend = viz::ScalarLegend{};
  options_.legend.title = title;
  options_.colourBar = values.size() > 0;
  if (mesh_) repaint3d();
  requestRender();
}

viz::ScenePaint SceneView::paint() {
  // The viz layer's paint: the same exposure, tone map and gamma as the exported figures.
  try {
    // The smooth scheme's structure is the mesh's: found at the first smooth paint, kept for the next.
    if (options_.image.smooth && !smoothing_) smoothing_ = std::make_unique<viz::SmoothInterpolation>(*mesh_);
    return viz::paintScene(*mesh_, data_, options_, smoothing_.get());
  } catch (const std::exception&) {
    return viz::ScenePaint{};  // data that does not fit: plain grey
  }
}

void SceneView::rebuildGeometry() {
  smoothing_ = nullptr;
  const viz::ScenePaint painted = paint();
  polyData_ = viz::makeElementPolyData(*mesh_, painted);
  ++geometryBuilds_;
  mapper_->SetInputData(polyData_);
  standIn_->rebuild(mesh_, painted);
  picker_ = nullptr;  // its cell locator was built on the old cells
  if (emitterOutline_) renderer()->RemoveActor(emitterOutline_);
  emitterOutline_ = nullptr;
  showColouring(painted);
  rebuildHighlight();
  rebuildEdges();
}

void SceneView::repaint3d() {
  const viz::ScenePaint painted = paint();
  viz::updateElementColours(*polyData_, painted);
  // The stand-in's colours are the clusters' means of the same corners: no geometry is built again.
  standIn_->recolour(painted);
  ++colourUpdates_;
  showColouring(painted);
}

void SceneView::showColouring(const viz::ScenePaint& painted) {
  // The light outline of the material view depends on the mesh alone: it stays while the colouring does.
  const bool outline = options_.colouring == viz::SceneColouring::Reflectance;
  if (outline && !emitterOutline_) {
    emitterOutline_ = viz::makeEmitterOutlineActor(*mesh_, 2.5 * devicePixelRatioF());
    if (emitterOutline_) renderer()->AddActor(emitterOutline_);
  } else if (!outline && emitterOutline_) {
    renderer()->RemoveActor(emitterOutline_);
    emitterOutline_ = nullptr;
  }
  if (colourBar_) renderer()->RemoveViewProp(colourBar_);
  colourBar_ = nullptr;
  if (painted.colourBar) {
    // The exported figures' bar (viz), in the right-hand strip of the view.
    colourBar_ = viz::makeColourBar(painted.legend.map, painted.legend.min, painted.legend.max,
                                    painted.legend.logScale, painted.legend.title, 14);
    colourBar_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    colourBar_->SetPosition(0.86, 0.12);
    colourBar_->SetPosition2(0.13, 0.76);
    renderer()->AddViewProp(colourBar_);
  }
}

void SceneView::setShowEdges(bool show) {
  options_.image.showEdges = show;
  if (show == showEdges_) return;
  showEdges_ = show;
  rebuildEdges();
  requestRender();
}

void SceneView::rebuildEdges() {
  if (edges_) edges_->removeFrom(*renderer());
  edges_ = nullptr;
  if (!showEdges_ || !mesh_) return;
  // The figures' edge lines (viz/mesh_edges.h), a lighter grey than theirs against the dark background.
  edges_ = viz::MeshEdgeLines::make(*mesh_, {0.2, 0.2, 0.2}, devicePixelRatioF());
  edges_->addTo(*renderer());
  edges_->actor()->SetVisibility(!inMotion_ || actor_->GetVisibility());
}

const viz::MeshEdgeLines* SceneView::meshEdges() const {
  return edges_;
}

void SceneView::setCaption(const QString& text) {
  caption_->SetInput(text.toUtf8().constData());
  fitCaption();
  requestRender();
}

void SceneView::resizeEvent(QResizeEvent* event) {
  VtkWidget::resizeEvent(event);
  fitCaption();
  fitViewAngle();
}

void SceneView::fitCaption() {
  const char* text = caption_->GetInput();
  const double characters = std::max<std::size_t>(1, text ? std::strlen(text) : 0);
  // About 0.6 em per character; 10 px margins on both sides.
  const double available = width() * devicePixelRatioF() - 20;
  caption_->GetTextProperty()->SetFontSize(
      std::clamp(static_cast<int>(available / (0.6 * characters)), 11, 18));
}

bool SceneView::showsColourBar() const {
  return colourBar_ != nullptr;
}

QString SceneView::caption() const {
  return QString::fromUtf8(caption_->GetInput() ? caption_->GetInput() : "");
}

void SceneView::setHighlighted(const std::vector<int>& elements) {
  highlighted_ = elements;
  rebuildHighlight();
  requestRender();
}

void SceneView::setRaySegments(const std::vector<viz::RaySegments>& segments) {
  for (const auto& actor : rayActors_) renderer()->RemoveActor(actor);
  rayActors_.clear();
  raySegments_ = 0;
  for (const viz::RaySegments& s : segments) {
    rayActors_.push_back(viz::linesActor(s.points, s.colour, s.width * devicePixelRatioF()));
    renderer()->AddActor(rayActors_.back());
    raySegments_ += static_cast<int>(s.points.size() / 2);
  }
  repaint3d();
}

void SceneView::rebuildHighlight() {
  if (!mesh_ || highlighted_.empty() || !polyData_) {
    highlightActor_->VisibilityOff();
    return;
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (int e : highlighted_) {
    if (e < 0 || e >= static_cast<int>(mesh_->size())) continue;
    const auto& vertices = mesh_->elements[e].vertices;
    cells->InsertNextCell(static_cast<vtkIdType>(vertices.size()));
    for (int v : vertices) cells->InsertCellPoint(points->InsertNextPoint(mesh_->vertices[v].data()));
  }
  auto outline = vtkSmartPointer<vtkPolyData>::New();
  outline->SetPoints(points);
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

vtkPolyData* SceneView::displayedPolyData() const {
  return polyData_;
}

vtkPolyData* SceneView::standInPolyData() const {
  return standIn_->polyData();
}

double SceneView::standInBuildMilliseconds() const {
  return standIn_->buildMilliseconds();
}

int SceneView::pickElement(QPoint position) {
  if (!mesh_ || !polyData_) return -1;
  endMotion();  // a click ends a wheel's motion: the pick sees the full mesh, never the stand-in
  if (!picker_) {
    // Without a locator the picker intersects the ray with every cell: a second at a million elements.
    // The locator is built at the first pick of a mesh (about as long as one of those linear picks) and
    // answers every later one in microseconds.
    auto locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    locator->SetDataSet(polyData_);
    locator->BuildLocator();
    picker_ = vtkSmartPointer<vtkCellPicker>::New();
    picker_->SetTolerance(0.0005);
    picker_->AddLocator(locator);
  }
  const double ratio = devicePixelRatioF();
  const double x = position.x() * ratio;
  const double y = (height() - 1 - position.y()) * ratio;
  if (!picker_->Pick(x, y, 0, renderer())) return -1;
  if (picker_->GetActor() != actor_.Get()) return -1;
  const vtkIdType cell = picker_->GetCellId();
  auto* ids = vtkIntArray::SafeDownCast(polyData_->GetCellData()->GetArray("element"));
  if (cell < 0 || !ids || cell >= ids->GetNumberOfTuples()) return -1;
  return ids->GetValue(cell);
}

}  // namespace rt::app
