#include "viz/cluster_view.h"

#include <vtkActor.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <array>
#include <stdexcept>

#include "viz/scene_view.h"
#include "viz/vtk_geometry.h"
#include "viz/vtk_render.h"
#include "viz/vtk_views.h"

namespace rt::viz {
namespace {

// The twelve edges of a box as segment end points, pushed out by a hair so that an edge lying on a wall
// is not hidden in it.
void addBoxEdges(const lesson::ClusterBox& box, double margin, std::vector<Vec3>& points) {
  const Vec3 lo = box.lower - Vec3::Constant(margin), hi = box.upper + Vec3::Constant(margin);
  auto corner = [&](int k) {
    return Vec3((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(), (k & 4) ? hi.z() : lo.z());
  };
  for (int k = 0; k < 8; ++k)
    for (int axis : {1, 2, 4})
      if (!(k & axis)) {
        points.push_back(corner(k));
        points.push_back(corner(k | axis));
      }
}

}  // namespace

void writeClusterFigure(const Mesh& mesh, const RgbField& B, const Camera& camera,
                        const std::vector<lesson::ClusterBox>& boxes, const ClusterViewOptions& options,
                        const std::string& path) {
  if (boxes.empty()) throw std::invalid_argument(path + ": no cluster boxes to draw");
  figureFormatOf(path);
  const double scale = options.size.fontScale();
  auto window = makeOffscreenWindow(options.size.width, options.size.height);

  SceneViewOptions sceneOptions;
  SceneViewData data;
  if (B.rows() == static_cast<Eigen::Index>(mesh.size()))
    data.B = B;
  else
    sceneOptions.colouring = SceneColouring::Reflectance;
  sceneOptions.dpi = options.size.dpi;
  const ScenePaint paint = paintScene(mesh, data, sceneOptions);
  const double full[4] = {0, 0, 1, 1};
  vtkSmartPointer<vtkRenderer> renderer =
      makeSceneRenderer(mesh, camera, paint, sceneOptions, options.size.height, full);
  // The room faint, so that the boxes behind its walls still show.
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor()) actor->GetProperty()->SetOpacity(0.45);
  window->AddRenderer(renderer);
  enableDepthPeeling(window, renderer);

  // Neighbouring boxes in the tree's order get different colours (Okabe-Ito).
  const std::array<Colour, 6> colours{{{0.902, 0.624, 0.0},
                                       {0.337, 0.706, 0.914},
                                       {0.0, 0.620, 0.451},
                                       {0.941, 0.894, 0.259},
                                       {0.0, 0.447, 0.698},
                                       {0.835, 0.369, 0.0}}};
  double extent = 0;
  for (const auto& box : boxes) extent = std::max(extent, (box.upper - box.lower).norm());
  const double lineWidth = std::max(1.5, 2.5 * scale);
  for (std::size_t c = 0; c < colours.size(); ++c) {
    std::vector<Vec3> points;
    for (std::size_t k = c; k < boxes.size(); k += colours.size())
      addBoxEdges(boxes[k], 0.002 * extent, points);
    if (!points.empty()) renderer->AddActor(linesActor(points, colours[c], lineWidth));
  }
  renderer->ResetCameraClippingRange();
  renderer->AddViewProp(
      makeCaption(options.caption, readableFontSize(options.size.height, scale, 0.028), options.size.width));
  writeRenderWindow(window, path, options.size.dpi);
}

}  // namespace rt::viz
