#include "core/polygon.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/convex_polygon.h"

namespace rt {

Vec3 newellNormal(const Polygon& polygon) {
  return twiceAreaVector(polygon.data(), static_cast<int>(polygon.size()));
}

double polygonArea(const Polygon& polygon) {
  return 0.5 * newellNormal(polygon).norm();
}

Vec3 polygonCentroid(const Polygon& polygon) {
  if (polygon.empty()) return Vec3::Zero();
  // Area-weighted centroid of the fan triangles; falls back to the vertex mean for degenerate polygons.
  Vec3 sum = Vec3::Zero();
  double total = 0;
  const Vec3 n = newellNormal(polygon);
  const double nn = n.norm();
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const double w = nn > 0 ? (polygon[i] - polygon[0]).cross(polygon[i + 1] - polygon[0]).dot(n) / nn : 0.0;
    sum += w * (polygon[0] + polygon[i] + polygon[i + 1]) / 3.0;
    total += w;
  }
  if (total > 0) return sum / total;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : polygon) mean += v;
  return mean / static_cast<double>(polygon.size());
}

double planarityDeviation(const Polygon& polygon) {
  const Vec3 n = newellNormal(polygon);
  const double len = n.norm();
  if (len == 0) return 0;
  const Vec3 unit = n / len;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : polygon) mean += v;
  mean /= static_cast<double>(polygon.size());
  double worst = 0;
  for (const Vec3& v : polygon) worst = std::max(worst, std::abs((v - mean).dot(unit)));
  return worst;
}

bool isConvex(const Polygon& polygon, const Vec3& normal) {
  const std::size_t count = polygon.size();
  if (count < 3) return false;
  // Relative tolerance so that collinear vertices (cross ~ 0) are accepted at any scale.
  const double scale = maxEdgeLength(polygon);
  const double eps = 1e-12 * scale * scale;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3& a = polygon[i];
    const Vec3& b = polygon[(i + 1) % count];
    const Vec3& c = polygon[(i + 2) % count];
    if ((b - a).cross(c - b).dot(normal) < -eps) return false;
  }
  return true;
}

std::vector<Polygon> fanTriangulate(const Polygon& polygon) {
  std::vector<Polygon> triangles;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
    triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
  return triangles;
}

double maxEdgeLength(const Polygon& polygon) {
  double worst = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    worst = std::max(worst, (polygon[(i + 1) % polygon.size()] - polygon[i]).norm());
  return worst;
}

double deviationFromFirstPlane(const Polygon& polygon) {
  if (polygon.size() < 4) return 0;
  const double scale = maxEdgeLength(polygon);
  for (std::size_t k = 2; k < polygon.size(); ++k) {
    const Vec3 n = (polygon[1] - polygon[0]).cross(polygon[k] - polygon[0]);
    if (n.norm() <= 1e-12 * scale * scale) continue;  // collinear so far: try the next vertex
    const Vec3 unit = n.normalized();
    double worst = 0;
    for (const Vec3& v : polygon) worst = std::max(worst, std::abs((v - polygon[0]).dot(unit)));
    return worst;
  }
  return 0;
}

double totalTurning(const Polygon& polygon, const Vec3& normal) {
  const std::size_t count = polygon.size();
  const Vec3 axis = normal.normalized();
  double total = 0;
  for (std::size_t i = 0; i < count; ++i) {
    // Edges projected onto the plane normal to `axis`, so that twisted (non-planar) outlines turn by their
    // projection.
    Vec3 in = polygon[(i + 1) % count] - polygon[i];
    Vec3 out = polygon[(i + 2) % count] - polygon[(i + 1) % count];
    in -= in.dot(axis) * axis;
    out -= out.dot(axis) * axis;
    total += std::atan2(in.cross(out).dot(axis), in.dot(out));
  }
  return total;
}

}  // namespace rt
