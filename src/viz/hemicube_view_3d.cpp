// The half cube over an element in its scene (VTK): pixels coloured by the element they see.
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

#include "viz/hemicube_view.h"
#include "viz/scene_view.h"
#include "viz/vtk_geometry.h"
#include "viz/vtk_render.h"
#include "viz/vtk_views.h"

namespace rt::viz {

void writeHemicube3dFigure(const Mesh& mesh, const HemicubeFaces& faces, const HemicubeViewOptions& options,
                           const std::string& path) {
  figureFormatOf(path);
  if (faces.element < 0 || static_cast<std::size_t>(faces.element) >= mesh.size())
    throw std::invalid_argument("the hemicube's element is not in the mesh");
  const double scale = options.size.fontScale();
  const Element& element = mesh.elements[faces.element];
  const double s = 0.5 * std::sqrt(element.area);  // half-size of the drawn cube
  auto toWorld = [&](const Vec3& local) {
    return Vec3(faces.origin + s * (local.x() * faces.u + local.y() * faces.v + local.z() * faces.normal));
  };

  // Camera: looking at the cube from in front of the element, above its horizon.
  Camera camera;
  camera.target = faces.origin + 0.45 * s * faces.normal;
  camera.position =
      camera.target + 5.0 * s * (0.55 * faces.u - 1.0 * faces.v + 0.9 * faces.normal).normalized();
  camera.up = faces.normal;
  camera.fovYDegrees = 35;

  auto window = makeOffscreenWindow(options.size.width, options.size.height);
  SceneViewOptions sceneOptions;
  sceneOptions.colouring = SceneColouring::Reflectance;
  sceneOptions.image.showEdges = true;
  sceneOptions.dpi = options.size.dpi;
  const double full[4] = {0, 0, 1, 1};
  vtkSmartPointer<vtkRenderer> renderer = makeSceneRenderer(mesh, camera, paintScene(mesh, {}, sceneOptions),
                                                            sceneOptions, options.size.height, full);
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor()) actor->GetProperty()->SetOpacity(0.25);
  window->AddRenderer(renderer);
  enableDepthPeeling(window, renderer);  // the faint room and the cube overlap
  renderer->AddActor(polygonActor(mesh.polygon(faces.element), {0.337, 0.706, 0.914}, 1.0));

  auto points = vtkSmartPointer<vtkPoints>::New();
  auto quads = vtkSmartPointer<vtkCellArray>::New();
  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetNumberOfComponents(3);
  const double maxDelta = maxDeltaFormFactor(faces.resolution);
  for (int f = 0; f < 5; ++f) {
    const auto face = static_cast<HemicubeFace>(f);
    const auto& buffer = faces.faces[static_cast<std::size_t>(f)];
    const std::vector<double>& deltas = deltaFormFactors(faces.resolution, face);
    for (int row = 0; row < buffer.height; ++row)
      for (int column = 0; column < buffer.width; ++column) {
        const std::size_t p = static_cast<std::size_t>(row) * buffer.width + column;
        quads->InsertNextCell(4);
        for (const Vec3& corner : hemicubePixelCorners(face, row, column, faces.resolution)) {
          const Vec3 w = toWorld(corner);
          quads->InsertCellPoint(points->InsertNextPoint(w.x(), w.y(), w.z()));
        }
        const int seen = buffer.element[p];
        const Rgb8 colour = options.colouring == HemicubeColouring::DeltaFormFactors
                                ? sampleColourMap(options.map, deltas[p] / maxDelta)
                            : seen >= 0                     ? categoryColour(seen)
                            : seen == kHemicubeSeesBackFace ? Rgb8{90, 90, 90}
                                                            : Rgb8{235, 235, 235};
        colours->InsertNextTypedTuple(colour.data());
      }
  }
  auto cube = vtkSmartPointer<vtkPolyData>::New();
  cube->SetPoints(points);
  cube->SetPolys(quads);
  cube->GetCellData()->SetScalars(colours);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(cube);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  auto cubeActor = vtkSmartPointer<vtkActor>::New();
  cubeActor->SetMapper(mapper);
  cubeActor->GetProperty()->LightingOff();
  cubeActor->GetProperty()->EdgeVisibilityOn();
  cubeActor->GetProperty()->SetEdgeColor(0.2, 0.2, 0.2);
  cubeActor->GetProperty()->SetLineWidth(faces.resolution <= 32 ? 1.0f : 0.0f);
  if (faces.resolution > 32) cubeActor->GetProperty()->EdgeVisibilityOff();
  renderer->AddActor(cubeActor);
  renderer->ResetCameraClippingRange();

  std::string caption = options.title;
  if (caption.empty())
    caption =
        "hemicube over element " + std::to_string(faces.element) + ": each pixel shows the element it sees";
  renderer->AddViewProp(
      makeCaption(caption, readableFontSize(options.size.height, scale, 0.028), options.size.width));
  writeRenderWindow(window, path, options.size.dpi);
}

// Here, beside the other VTK writer, so that hemicube_view.cpp stays free of VTK (the web module draws the
// same figure from hemicubeFacesDrawing).
void writeHemicubeFacesFigure(const HemicubeFaces& faces, std::size_t elements,
                              const HemicubeViewOptions& options, const std::string& path) {
  writeDrawing(hemicubeFacesDrawing(faces, elements, options), path);
}

}  // namespace rt::viz
