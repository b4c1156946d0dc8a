// The 3D Nusselt construction (VTK): hemisphere, receiver, rays, projections on the hemisphere and on the
// disk.
#include <vtkActor.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <cstdio>

#include "viz/nusselt_view.h"
#include "viz/vtk_geometry.h"
#include "viz/vtk_render.h"

namespace rt::viz {

void writeNusseltHemisphereFigure(const NusseltConstruction& c, const NusseltViewOptions& options,
                                  const std::string& path) {
  figureFormatOf(path);
  const double scale = options.size.fontScale();
  auto window = makeOffscreenWindow(options.size.width, options.size.height);
  // Depth peeling: the glass hemisphere in front of the disk and the projections.
  auto renderer = addConstructionRenderer(window);

  // The unit hemisphere is drawn at a radius that suits the scene: half the distance to the receiver.
  Vec3 receiverCentre = Vec3::Zero();
  for (const Vec3& p : c.receiver) receiverCentre += p / static_cast<double>(c.receiver.size());
  const double R = std::max(1e-9, 0.5 * (receiverCentre - c.point).norm());
  const Colour orange{0.902, 0.624, 0.0}, sky{0.337, 0.706, 0.914}, blue{0.0, 0.447, 0.698},
      dark{0.1, 0.1, 0.1};
  renderer->AddActor(hemisphereActor(c.point, c.u, c.v, c.normal, R, {0.85, 0.85, 0.88}, 0.28, false));
  renderer->AddActor(hemisphereActor(c.point, c.u, c.v, c.normal, 1.001 * R, {0.55, 0.55, 0.6}, 1.0, true));
  std::vector<Vec3> disk;
  for (int k = 0; k < 128; ++k) {
    const double a = 2 * M_PI * k / 128;
    disk.push_back(c.point + R * (std::cos(a) * c.u + std::sin(a) * c.v));
  }
  renderer->AddActor(polygonActor(disk, {0.92, 0.92, 0.94}, 1.0));
  renderer->AddActor(loopActor(disk, dark, 1.5 * scale));

  // The receiver (whole, faint where it is behind the horizon) and its visible part.
  renderer->AddActor(polygonActor(c.receiver, orange, c.visible.size() >= 3 ? 0.35 : 0.8));
  if (c.visible.size() >= 3) renderer->AddActor(polygonActor(c.visible, orange, 1.0));

  if (c.onHemisphere.size() >= 3) {
    // On the hemisphere: a fan from the contour's mean direction, lifted a little off the surface.
    Vec3 centre = Vec3::Zero();
    for (const Vec3& d : c.onHemisphere) centre += d;
    centre.normalize();
    std::vector<Vec3> fan;
    for (std::size_t k = 0; k < c.onHemisphere.size(); ++k) {
      fan.push_back(c.point + 1.003 * R * centre);
      fan.push_back(c.point + 1.003 * R * c.onHemisphere[k]);
      fan.push_back(c.point + 1.003 * R * c.onHemisphere[(k + 1) % c.onHemisphere.size()]);
    }
    renderer->AddActor(trianglesActor(fan, sky, 0.95));
    std::vector<Vec3> contour, onDisk, rays, drops;
    for (std::size_t k = 0; k < c.onHemisphere.size(); ++k) {
      contour.push_back(c.point + 1.004 * R * c.onHemisphere[k]);
      onDisk.push_back(c.point + R * (c.onDisk[k].x() * c.u + c.onDisk[k].y() * c.v + 0.004 * c.normal));
    }
    renderer->AddActor(loopActor(contour, blue, 2.5 * scale));
    renderer->AddActor(polygonActor(onDisk, sky, 1.0));
    renderer->AddActor(loopActor(onDisk, blue, 2.5 * scale));
    // Rays to the visible corners, and the drop from each corner's image on the hemisphere to the disk.
    for (const Vec3& corner : c.visible) {
      rays.push_back(c.point);
      rays.push_back(corner);
      const Vec3 d = (corner - c.point).normalized();
      drops.push_back(c.point + R * d);
      drops.push_back(c.point + R * (d.dot(c.u) * c.u + d.dot(c.v) * c.v));
    }
    renderer->AddActor(linesActor(rays, dark, 1.5 * scale));
    renderer->AddActor(linesActor(drops, blue, 1.5 * scale));
  }
  renderer->AddActor(pointsActor({c.point}, dark, 0.025 * R));

  frameFromDirection(renderer, 1.2 * c.u - 2.2 * c.v + 1.3 * c.normal, c.normal, 1.05);

  char text[200];
  std::snprintf(text, sizeof text, "%s\nprojected area / pi = %.5f    exact F = %.5f", options.title.c_str(),
                c.diskAreaFraction, c.exact);
  renderer->AddViewProp(
      makeCaption(text, readableFontSize(options.size.height, scale, 0.03), options.size.width));
  writeRenderWindow(window, path, options.size.dpi);
}

}  // namespace rt::viz
