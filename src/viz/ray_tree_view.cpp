#include "viz/ray_tree_view.h"

#include <vtkActor.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <algorithm>

#include "viz/faded_scene.h"
#include "viz/vtk_geometry.h"
#include "viz/vtk_render.h"

namespace rt::viz {

std::vector<RaySegments> rayTreeSegments(const RayTree& tree) {
  // Okabe-Ito: colour-blind safe, as the charts.
  std::vector<RaySegments> kinds{{"primary", {0.0, 0.447, 0.698}, 3, {}},
                                 {"reflection", {0.8, 0.475, 0.655}, 3, {}},
                                 {"shadow: reaches the light", {0.902, 0.624, 0.0}, 1.5, {}},
                                 {"shadow: blocked", {0.0, 0.0, 0.0}, 1.5, {}}};
  for (const RayNode& n : tree.nodes) {
    const std::size_t k = n.kind == RayKind::Primary      ? 0
                          : n.kind == RayKind::Reflection ? 1
                          : n.blocked                     ? 3
                                                          : 2;
    kinds[k].points.push_back(n.origin);
    kinds[k].points.push_back(n.end);
  }
  kinds.erase(
      std::remove_if(kinds.begin(), kinds.end(), [](const RaySegments& s) { return s.points.empty(); }),
      kinds.end());
  return kinds;
}

Camera rayTreeCamera(const Mesh& mesh, const Camera& eye) {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  box.extend(eye.position);
  const Vec3 centre = box.center();
  const Vec3 forward = (eye.target - eye.position).normalized();
  const Vec3 up = eye.up.normalized();
  const Vec3 side = forward.cross(up).normalized();
  const double size = box.diagonal().norm();
  Camera c;
  c.target = centre;
  // From the eye's right and above, far enough back that the eye and the room both fit.
  c.position = centre + size * (0.9 * side + 0.45 * up - 0.55 * forward).normalized();
  c.up = up;
  c.fovYDegrees = 50;
  return c;
}

void writeRayTreeFigure(const Mesh& mesh, const Camera& camera, const RayTree& tree,
                        const RayTreeViewOptions& options, const std::string& path) {
  figureFormatOf(path);
  const double scale = options.size.fontScale();
  auto window = makeOffscreenWindow(options.size.width, options.size.height);
  vtkSmartPointer<vtkRenderer> renderer = addFadedScene(mesh, camera, options.size, window);
  std::vector<Vec3> hits;
  for (const RayNode& n : tree.nodes)
    if (n.kind != RayKind::Shadow && n.element >= 0) hits.push_back(n.end);
  for (const RaySegments& s : rayTreeSegments(tree))
    renderer->AddActor(linesActor(s.points, s.colour, std::max(1.0, s.width * scale)));
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  const double size = Vec3(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]).norm();
  if (!hits.empty()) renderer->AddActor(pointsActor(hits, {0.1, 0.1, 0.1}, 0.006 * size));
  renderer->ResetCameraClippingRange();
  renderer->AddViewProp(
      makeCaption(options.caption, readableFontSize(options.size.height, scale, 0.026), options.size.width));
  writeRenderWindow(window, path, options.size.dpi);
}

}  // namespace rt::viz
