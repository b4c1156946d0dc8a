#include "core/raytrace/thin_lens.h"

#include <cmath>
#include <numbers>

namespace rt {
namespace {

struct Frame {
  Vec3 forward, right, up;
};

Frame frameOf(const Camera& camera) {
  const Vec3 forward = (camera.target - camera.position).normalized();
  const Vec3 right = forward.cross(camera.up).normalized();
  return {forward, right, right.cross(forward)};
}

}  // namespace

double focusDistanceOf(const Camera& camera, const ThinLens& lens) {
  return lens.focusDistance > 0 ? lens.focusDistance : (camera.target - camera.position).norm();
}

LensRay thinLensRay(const Camera& camera, const ThinLens& lens, const Vec3& pinholeDirection, double u,
                    double v) {
  if (!(lens.radius > 0)) return {camera.position, pinholeDirection};
  const Frame frame = frameOf(camera);
  const double f = focusDistanceOf(camera, lens);
  // The plane of focus is perpendicular to the view direction, so the pinhole ray reaches it after f / cos.
  const Vec3 focus = camera.position + (f / pinholeDirection.dot(frame.forward)) * pinholeDirection;
  // Uniform over the disc: the radius goes as the square root, the area within it being proportional to r^2.
  const double r = lens.radius * std::sqrt(u), phi = 2 * std::numbers::pi * v;
  const Vec3 origin = camera.position + r * (std::cos(phi) * frame.right + std::sin(phi) * frame.up);
  return {origin, (focus - origin).normalized()};
}

double blurDiscPixels(const Camera& camera, const ThinLens& lens, int height, double depth) {
  if (!(lens.radius > 0) || !(depth > 0) || height <= 0) return 0.0;
  const double f = focusDistanceOf(camera, lens);
  const double angle = 2 * lens.radius * std::abs(1 / f - 1 / depth);
  const double pixelAngle = 2 * std::tan(camera.fovYDegrees * std::numbers::pi / 360.0) / height;
  return angle / pixelAngle;
}

}  // namespace rt
