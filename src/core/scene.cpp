#include "core/scene.h"

#include <algorithm>
#include <cmath>

namespace rt {

bool Scene::hasEmitter() const {
  return std::any_of(patches.begin(), patches.end(),
                     [&](const Patch& p) { return materialOf(p).isEmitter(); });
}

double Scene::totalArea() const {
  double total = 0;
  for (const Patch& p : patches) total += p.area;
  return total;
}

Eigen::AlignedBox3d Scene::bounds() const {
  Eigen::AlignedBox3d box;
  for (const Patch& p : patches)
    for (const Vec3& v : p.vertices) box.extend(v);
  return box;
}

const Camera* Scene::findCamera(const std::string& name) const {
  for (const NamedCamera& c : cameras)
    if (c.name == name) return &c.camera;
  return nullptr;
}

Camera Scene::cameraOrDefault() const {
  if (camera) return *camera;
  Camera c;
  const Eigen::AlignedBox3d box = bounds();
  if (box.isEmpty()) return c;
  const Vec3 centre = box.center();
  const double radius = 0.5 * box.diagonal().norm();
  c.target = centre;
  c.fovYDegrees = 40.0;
  const double distance = radius / std::tan(0.5 * c.fovYDegrees * M_PI / 180.0) * 1.1;
  // Looking along -z with +y up, slightly from above: a readable default for most scenes.
  c.position = centre + distance * Vec3(0.35, 0.45, 1.0).normalized();
  c.up = Vec3(0, 1, 0);
  return c;
}

}  // namespace rt
