#include "viz/vtk_views.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>

#include <algorithm>
#include <map>
#include <utility>

#include "viz/element_polydata.h"
#include "viz/mesh_edges.h"
#include "viz/vtk_render.h"

namespace rt::viz {
namespace {

// Okabe-Ito vermillion: the marker colour of a highlighted element (not in viridis or cividis).
constexpr double kHighlight[3] = {0.835, 0.369, 0.0};
// Okabe-Ito yellow: the outline of a light in material views.
constexpr double kEmitterOutline[3] = {0.941, 0.894, 0.259};

// The element filled with the marker colour and outlined in white (by the edge lines: they stay right when
// the element reaches behind the camera).
void addHighlight(vtkRenderer& renderer, const Mesh& mesh, int element, double lineWidth) {
  const Element& marked = mesh.elements[static_cast<std::size_t>(element)];
  Mesh one;  // the element alone, with its own corners
  one.elements = {marked};
  for (std::size_t k = 0; k < marked.vertices.size(); ++k) {
    one.vertices.push_back(mesh.vertices[static_cast<std::size_t>(marked.vertices[k])]);
    one.elements[0].vertices[k] = static_cast<int>(k);
  }
  ScenePaint single;
  single.firstCorner = {0, static_cast<int>(marked.vertices.size())};
  single.colours.assign(marked.vertices.size(), Rgb8{213, 94, 0});
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(makeElementPolyData(one, single));
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(kHighlight[0], kHighlight[1], kHighlight[2]);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->BackfaceCullingOn();
  renderer.AddActor(actor);
  MeshEdgeLines::make(one, {1, 1, 1}, lineWidth)->addTo(renderer);
}

}  // namespace

vtkSmartPointer<vtkActor> makeEmitterOutlineActor(const Mesh& mesh, double lineWidth) {
  // Edges keyed by their two vertex indices: an edge two emitting elements share is inside the light.
  std::map<std::pair<int, int>, std::pair<int, int>> edges;  // key -> (count, element)
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    if (mesh.emission.row(static_cast<Eigen::Index>(e)).maxCoeff() <= 0) continue;
    const auto& vs = mesh.elements[e].vertices;
    for (std::size_t k = 0; k < vs.size(); ++k) {
      const int a = vs[k], b = vs[(k + 1) % vs.size()];
      auto& entry = edges[{std::min(a, b), std::max(a, b)}];
      ++entry.first;
      entry.second = static_cast<int>(e);
    }
  }
  if (edges.empty()) return nullptr;
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double lift = 1e-3 * (hi - lo).norm();
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& [key, entry] : edges) {
    if (entry.first != 1) continue;
    const Vec3 offset = lift * mesh.elements[static_cast<std::size_t>(entry.second)].normal;
    const Vec3 a = mesh.vertices[static_cast<std::size_t>(key.first)] + offset;
    const Vec3 b = mesh.vertices[static_cast<std::size_t>(key.second)] + offset;
    const vtkIdType ids[2] = {points->InsertNextPoint(a.x(), a.y(), a.z()),
                              points->InsertNextPoint(b.x(), b.y(), b.z())};
    lines->InsertNextCell(2, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(kEmitterOutline[0], kEmitterOutline[1], kEmitterOutline[2]);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetLineWidth(static_cast<float>(lineWidth));
  return actor;
}

vtkSmartPointer<vtkRenderer> makeSceneRenderer(const Mesh& mesh, const Camera& camera,
                                               const ScenePaint& paint, const SceneViewOptions& options,
                                               int windowHeight, const double viewport[4]) {
  const double scale = options.dpi > 0 ? options.dpi / 96.0 : 1.0;
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  renderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
  renderer->UseFXAAOn();

  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(makeElementPolyData(mesh, paint));
  mapper->SetScalarModeToUsePointData();
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  // The colour is the displayed quantity itself: no lighting, and one-sided polygons as in the model.
  // Material and id views get a mild headlight: without the shading of light, a white block in front of a
  // white wall vanishes.
  const bool shapeShading =
      options.colouring == SceneColouring::Reflectance || options.colouring == SceneColouring::ElementId;
  actor->GetProperty()->SetLighting(shapeShading);
  if (shapeShading) {
    actor->GetProperty()->SetAmbient(0.6);
    actor->GetProperty()->SetDiffuse(0.4);
    actor->GetProperty()->SetSpecular(0.0);
  }
  actor->GetProperty()->BackfaceCullingOn();
  if (!options.image.smooth) actor->GetProperty()->SetInterpolationToFlat();
  renderer->AddActor(actor);
  if (options.image.showEdges)
    MeshEdgeLines::make(mesh, options.edgeColour, std::max(1.0, options.edgeWidth * scale))->addTo(*renderer);
  if (options.colouring == SceneColouring::Reflectance)
    if (auto outline = makeEmitterOutlineActor(mesh, std::max(2.0, 2.5 * scale))) renderer->AddActor(outline);
  if (paint.highlightElement >= 0 && static_cast<std::size_t>(paint.highlightElement) < mesh.size())
    addHighlight(*renderer, mesh, paint.highlightElement, std::max(2.0, 3.0 * scale));

  vtkCamera* view = renderer->GetActiveCamera();
  view->SetPosition(camera.position.x(), camera.position.y(), camera.position.z());
  view->SetFocalPoint(camera.target.x(), camera.target.y(), camera.target.z());
  view->SetViewUp(camera.up.x(), camera.up.y(), camera.up.z());
  view->SetViewAngle(camera.fovYDegrees);
  view->OrthogonalizeViewUp();
  renderer->ResetCameraClippingRange();

  if (!options.caption.empty())
    renderer->AddViewProp(makeCaption(options.caption, readableFontSize(windowHeight, scale, 0.028)));
  return renderer;
}

void addSceneView(vtkRenderWindow* window, const Mesh& mesh, const Camera& camera, const SceneViewData& data,
                  const SceneViewOptions& options) {
  const ScenePaint paint = paintScene(mesh, data, options);
  const int height = window->GetSize()[1] > 0 ? window->GetSize()[1] : options.image.height;
  const bool bar = paint.colourBar;
  const double sceneViewport[4] = {0.0, 0.0, bar ? 0.78 : 1.0, 1.0};
  window->AddRenderer(makeSceneRenderer(mesh, camera, paint, options, height, sceneViewport));
  if (!bar) return;
  auto barRenderer = vtkSmartPointer<vtkRenderer>::New();
  barRenderer->SetViewport(0.78, 0.0, 1.0, 1.0);
  barRenderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
  const double scale = options.dpi > 0 ? options.dpi / 96.0 : 1.0;
  auto colourBar = makeColourBar(paint.legend.map, paint.legend.min, paint.legend.max, paint.legend.logScale,
                                 paint.legend.title, readableFontSize(height, scale, 0.024));
  colourBar->SetPosition(0.08, 0.08);
  colourBar->SetPosition2(0.84, 0.8);
  barRenderer->AddViewProp(colourBar);
  window->AddRenderer(barRenderer);
}

void writeSceneFigure(const Mesh& mesh, const Camera& camera, const SceneViewData& data,
                      const SceneViewOptions& options, const std::string& path) {
  figureFormatOf(path);  // reject unknown extensions before rendering
  auto window = makeOffscreenWindow(options.image.width, options.image.height);
  addSceneView(window, mesh, camera, data, options);
  writeRenderWindow(window, path, options.dpi);
}

}  // namespace rt::viz
