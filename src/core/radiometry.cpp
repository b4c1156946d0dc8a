#include "core/radiometry.h"

#include <cmath>
#include <numbers>

#include "core/polygon.h"

namespace rt {

double polygonSolidAngle(const Vec3& point, const Polygon& polygon) {
  if (polygon.size() < 3) return 0.0;
  const Vec3 a = polygon[0] - point;
  const double ra = a.norm();
  double sum = 0.0;
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    const Vec3 b = polygon[k] - point, c = polygon[k + 1] - point;
    const double rb = b.norm(), rc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = ra * rb * rc + a.dot(b) * rc + a.dot(c) * rb + b.dot(c) * ra;
    // atan2 keeps the half-angle's quadrant: a triangle subtending more than a hemisphere has a negative
    // denominator.
    sum += 2.0 * std::atan2(numerator, denominator);
  }
  // The fan's triangles share the polygon's winding, so their signed angles add; the sign only says from
  // which side the point sees the polygon.
  return std::abs(sum);
}

double smallPatchSolidAngle(const Vec3& point, const Polygon& polygon) {
  if (polygon.size() < 3) return 0.0;
  const Vec3 toPatch = polygonCentroid(polygon) - point;
  const double r2 = toPatch.squaredNorm();
  if (!(r2 > 0)) return 0.0;
  const Vec3 normal = newellNormal(polygon).normalized();
  const double cosTheta = std::abs(normal.dot(toPatch)) / std::sqrt(r2);
  return polygonArea(polygon) * cosTheta / r2;
}

double hemisphereCosineIntegral(int rings) {
  if (rings < 1) return 0.0;
  const double dTheta = 0.5 * std::numbers::pi / rings;
  double sum = 0.0;
  for (int k = 0; k < rings; ++k) {
    const double theta = (k + 0.5) * dTheta;
    sum += std::cos(theta) * std::sin(theta) * dTheta;
  }
  return 2.0 * std::numbers::pi * sum;
}

}  // namespace rt
