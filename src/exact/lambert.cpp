// Lambert's point-to-polygon form factor (1760; Baum, Rushmeier & Winget 1989 for radiosity) and horizon
// clipping.
#include <cmath>
#include <numbers>

#include "core/polygon.h"
#include "exact/exact_reference.h"
#include "exact/geometry_util.h"

namespace rt::exact {

// -(1/2pi) sum_k beta_k n . gamma_k for a closed contour, without any facing test: positive for a contour
// that is CCW seen from the side x is on, negative for a clockwise one (so holes subtract).
double lambertContourSum(const Vec3& x, const Vec3& n, const Polygon& contour) {
  double sum = 0;
  const std::size_t count = contour.size();
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3 a = contour[k] - x;
    const Vec3 b = contour[(k + 1) % count] - x;
    const Vec3 g = a.cross(b);
    const double gn = g.norm();
    if (gn == 0) continue;  // edge collinear with x: contributes nothing
    const double beta = std::atan2(gn, a.dot(b));
    sum += beta * n.dot(g) / gn;
  }
  return -sum / (2 * std::numbers::pi);
}

double PolygonWithHoles::area() const {
  double a = polygonArea(outer);
  for (const Polygon& h : holes) a -= polygonArea(h);
  return a;
}

double pointToPolygonFormFactor(const Vec3& x, const Vec3& n, const Polygon& polygon) {
  if (polygon.size() < 3) return 0;
  const Vec3 front = newellNormal(polygon);
  if ((x - polygon[0]).dot(front) <= 0) return 0;  // x sees the back (or the polygon edge-on)
  return std::max(0.0, lambertContourSum(x, n, polygon));
}

double pointToPolygonFormFactorClipped(const Vec3& x, const Vec3& n, const Polygon& polygon) {
  return pointToPolygonFormFactor(x, n, clipToHalfspace(polygon, x, n));
}

double pointToRegionFormFactor(const Vec3& x, const Vec3& n, const std::vector<PolygonWithHoles>& regions) {
  double total = 0;
  for (const PolygonWithHoles& region : regions) {
    if (region.outer.size() < 3) continue;
    const Vec3 front = newellNormal(region.outer);
    if ((x - region.outer[0]).dot(front) <= 0) continue;
    total += lambertContourSum(x, n, region.outer);
    for (const Polygon& hole : region.holes) total += lambertContourSum(x, n, hole);
  }
  return std::max(0.0, total);
}

}  // namespace rt::exact
