#include "app/camera_views.h"

#include <array>
#include <cmath>

namespace rt::app {
namespace {

double tanHalf(double fovYDegrees) {
  return std::tan(0.5 * fovYDegrees * M_PI / 180.0);
}

// Looking at the box along -direction from outside, far enough that a sphere around it fits the view.
Camera framing(const Eigen::AlignedBox3d& box, const Vec3& direction, const Vec3& up, double fovYDegrees) {
  Camera c;
  c.fovYDegrees = fovYDegrees;
  c.target = box.center();
  const double radius = std::max(0.5 * box.diagonal().norm(), 1e-9);
  c.position = c.target + direction * (radius / std::sin(0.5 * fovYDegrees * M_PI / 180.0) * 1.02);
  c.up = up;
  return c;
}

}  // namespace

Vec3 openSide(const Scene& scene) {
  const Eigen::AlignedBox3d box = scene.bounds();
  if (box.isEmpty() || scene.patches.empty()) return Vec3::Zero();
  const Vec3 size = box.sizes();
  // Walls of measured rooms are not quite planes of the box (the Cornell box's are off by a few millimetres):
  // a patch within 2 % of the box's depth from a side counts as that side's wall.
  const Vec3 eps = 0.02 * size + Vec3::Constant(1e-9 * size.norm());
  // Area of inward-facing patches lying in each side's plane, as a fraction of that side.
  std::array<double, 6> covered{};
  for (const Patch& p : scene.patches) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int s = 0; s < 2; ++s) {
        const double plane = s == 0 ? box.min()[axis] : box.max()[axis];
        const double inward = s == 0 ? p.normal[axis] : -p.normal[axis];
        if (inward < 0.9) continue;
        bool onPlane = true;
        for (const Vec3& v : p.vertices) onPlane = onPlane && std::abs(v[axis] - plane) < eps[axis];
        if (onPlane) covered[static_cast<std::size_t>(2 * axis + s)] += p.area;
      }
    }
  }
  int walled = 0;
  int open = -1;
  double least = 1.0;
  // The OBJ convention's front (+z) first, so that a box open on two sides is seen from its front.
  for (int side : {5, 4, 1, 0, 3, 2}) {
    const int axis = side / 2;
    const double area = size[(axis + 1) % 3] * size[(axis + 2) % 3];
    const double fraction = area > 0 ? covered[static_cast<std::size_t>(side)] / area : 0.0;
    if (fraction >= 0.5) ++walled;
    if (fraction < 0.5 && fraction < least) {
      least = fraction;
      open = side;
    }
  }
  // A room: walled on all other sides (a floor plan open on top counts as well).
  if (open < 0 || walled < 5) return Vec3::Zero();
  Vec3 direction = Vec3::Zero();
  direction[open / 2] = open % 2 == 0 ? -1.0 : 1.0;
  return direction;
}

Camera sceneCamera(const Scene& scene) {
  if (scene.camera) return *scene.camera;
  const Eigen::AlignedBox3d box = scene.bounds();
  if (box.isEmpty()) return Camera{};
  const Vec3 side = openSide(scene);
  if (side.isZero()) return standardCamera(scene, StandardView::Front);
  // From outside the open side, at the distance where the opening fills the view: inside, every wall shows.
  Camera c;
  c.fovYDegrees = 40.0;
  c.target = box.center();
  int axis = 0;
  side.cwiseAbs().maxCoeff(&axis);
  c.up = axis == 1 ? Vec3(0, 0, -side[1]) : Vec3(0, 1, 0);
  const Vec3 size = box.sizes();
  double halfOpening = 0;
  for (int k = 0; k < 3; ++k)
    if (k != axis) halfOpening = std::max(halfOpening, 0.5 * size[k]);
  const double distance = 0.5 * size[axis] + halfOpening / tanHalf(c.fovYDegrees) * 1.05;
  c.position = c.target + side * distance;
  return c;
}

Vec3 frontDirection(const Scene& scene) {
  const Eigen::AlignedBox3d box = scene.bounds();
  Vec3 towardsEye = Vec3::Zero();
  if (scene.camera && !box.isEmpty())
    towardsEye = scene.camera->position - box.center();
  else
    towardsEye = openSide(scene);
  // The horizontal axis (x or z) nearest the direction: the front is level, whatever the eye's height.
  towardsEye.y() = 0;
  if (towardsEye.squaredNorm() == 0) return Vec3(0, 0, 1);
  const int axis = std::abs(towardsEye.x()) > std::abs(towardsEye.z()) ? 0 : 2;
  Vec3 front = Vec3::Zero();
  front[axis] = towardsEye[axis] < 0 ? -1.0 : 1.0;
  return front;
}

Camera standardCamera(const Scene& scene, StandardView view, double fovYDegrees) {
  const Eigen::AlignedBox3d box = scene.bounds();
  const Vec3 up(0, 1, 0), front = frontDirection(scene);
  switch (view) {
    case StandardView::Top:
      return framing(box, up, -front, fovYDegrees);  // the front at the bottom of the picture
    case StandardView::Side:
      return framing(box, up.cross(front), up, fovYDegrees);  // the right-hand side, seen from the front
    case StandardView::Front:
    default:
      return framing(box, front, up, fovYDegrees);
  }
}

}  // namespace rt::app
