// The solid-angle construction (VTK): sphere, patch, rays and the patch's projection on the sphere.
#include "viz/solid_angle_view.h"

#include <vtkActor.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <cstdio>

#include "core/polygon.h"
#include "viz/vtk_geometry.h"
#include "viz/vtk_render.h"

namespace rt::viz {

SolidAngleConstruction solidAngleConstruction(const Vec3& point, const Polygon& patch, double solidAngle,
                                              double smallPatch, int samplesPerEdge) {
  SolidAngleConstruction c;
  c.point = point;
  c.patch = patch;
  c.solidAngle = solidAngle;
  c.smallPatch = smallPatch;
  const Vec3 toCentre = polygonCentroid(patch) - point;
  c.distance = toCentre.norm();
  const Vec3 normal = newellNormal(patch).normalized();
  c.tiltDegrees = std::acos(std::min(1.0, std::abs(normal.dot(toCentre)) / c.distance)) * 180 / M_PI;
  // Half the distance to the nearest corner: the sphere stays between the point and the patch.
  double nearest = c.distance;
  for (const Vec3& corner : patch) nearest = std::min(nearest, (corner - point).norm());
  c.radius = 0.5 * nearest;
  for (std::size_t k = 0; k < patch.size(); ++k)
    for (int t = 0; t < samplesPerEdge; ++t) {
      const Vec3 q = patch[k] + (patch[(k + 1) % patch.size()] - patch[k]) * (double(t) / samplesPerEdge);
      c.onSphere.push_back((q - point).normalized());
    }
  return c;
}

void writeSolidAngleFigure(const SolidAngleConstruction& c, const SolidAngleViewOptions& options,
                           const std::string& path) {
  figureFormatOf(path);
  const double scale = options.size.fontScale();
  auto window = makeOffscreenWindow(options.size.width, options.size.height);
  auto renderer = addConstructionRenderer(window);  // the glass sphere in front of the projection

  const Colour orange{0.902, 0.624, 0.0}, sky{0.337, 0.706, 0.914}, blue{0.0, 0.447, 0.698},
      dark{0.1, 0.1, 0.1};
  const double R = c.radius;
  // The sphere about the point, as two glass hemispheres around the axis to the patch.
  const Vec3 axis = (polygonCentroid(c.patch) - c.point).normalized();
  const Vec3 u = axis.unitOrthogonal(), v = axis.cross(u);
  for (const double side : {1.0, -1.0}) {
    const Vec3 n = side * axis, w = side * v;  // u x w = n: right-handed on both halves
    renderer->AddActor(hemisphereActor(c.point, u, w, n, R, {0.85, 0.85, 0.88}, 0.22, false));
    renderer->AddActor(hemisphereActor(c.point, u, w, n, 1.001 * R, {0.6, 0.6, 0.65}, 0.6, true));
  }
  renderer->AddActor(polygonActor(c.patch, orange, 1.0));
  renderer->AddActor(loopActor(c.patch, dark, 1.5 * scale));

  // The projection: a fan from the outline's mean direction, lifted a little off the sphere.
  Vec3 centre = Vec3::Zero();
  for (const Vec3& d : c.onSphere) centre += d;
  centre.normalize();
  std::vector<Vec3> fan, outline, rays;
  for (std::size_t k = 0; k < c.onSphere.size(); ++k) {
    fan.push_back(c.point + 1.004 * R * centre);
    fan.push_back(c.point + 1.004 * R * c.onSphere[k]);
    fan.push_back(c.point + 1.004 * R * c.onSphere[(k + 1) % c.onSphere.size()]);
    outline.push_back(c.point + 1.005 * R * c.onSphere[k]);
  }
  renderer->AddActor(trianglesActor(fan, sky, 0.95));
  renderer->AddActor(loopActor(outline, blue, 2.5 * scale));
  for (const Vec3& corner : c.patch) {
    rays.push_back(c.point);
    rays.push_back(corner);
  }
  renderer->AddActor(linesActor(rays, dark, 1.5 * scale));
  renderer->AddActor(pointsActor({c.point}, dark, 0.04 * R));

  // Seen from beside the axis the patch turns about, and from its front: its tilt, its distance and its
  // face all show.
  const Vec3 normal = newellNormal(c.patch).normalized();
  Vec3 turn = axis.cross(normal);
  turn = turn.norm() > 1e-6 ? turn.normalized() : u;
  frameFromDirection(renderer, 1.5 * turn + (normal.dot(axis) < 0 ? 1.0 : -1.0) * normal, axis, 1.05);

  char text[320];
  std::snprintf(text, sizeof text,
                "%s: r = %.3g m, tilt %.3g deg\nexact %.5f sr, A cos(theta) / r^2 = %.5f sr (%+.2f%%)",
                options.title.c_str(), c.distance, c.tiltDegrees, c.solidAngle, c.smallPatch,
                100.0 * (c.smallPatch / c.solidAngle - 1.0));
  renderer->AddViewProp(
      makeCaption(text, readableFontSize(options.size.height, scale, 0.026), options.size.width));
  writeRenderWindow(window, path, options.size.dpi);
}

}  // namespace rt::viz
