#include "core/geometry/plane_clip.h"

namespace rt {

bool clipToFront(const Vec3* in, int count, const Vec3& origin, const Vec3& normal, double eps,
                 ConvexPolygon& out) {
  out.count = 0;
  const double length2 = normal.squaredNorm();
  if (count < 3 || !(length2 > 0)) return false;
  // Heights times the normal's length: within eps of the plane where d^2 <= eps^2 |normal|^2 (no root
  // or division per corner; the cut points depend only on the heights' ratios).
  const double margin2 = eps * eps * length2;
  double local[ConvexPolygon::kInline];
  double* side = count <= ConvexPolygon::kInline ? local : plane_clip_detail::spilledHeights<1>(count);
  bool anyBehind = false, anyFront = false;
  for (int k = 0; k < count; ++k) {
    double d = normal.dot(in[k] - origin);
    if (d * d <= margin2) d = 0;
    side[k] = d;
    anyBehind |= d < 0;
    anyFront |= d > 0;
  }
  if (!anyFront) return false;
  if (!anyBehind) {
    out.assign(in, count);
    return true;
  }
  out.v.reserve(2 * count);  // each corner adds itself and a cut at most, whatever rounding says
  cutByHeights(
      in, side, count, [&](const Vec3& p) { out.v[static_cast<std::size_t>(out.count++)] = p; },
      [](const Vec3&) {});
  if (out.count < 3) out.count = 0;
  return false;
}

void clipToHalfspace(const Polygon& polygon, const Vec3& point, const Vec3& normal, Polygon& out) {
  const std::size_t n = polygon.size();
  constexpr std::size_t kStack = 64;
  double stackSide[kStack];
  std::vector<double> heapSide(n > kStack ? n : 0);
  double* side = n > kStack ? heapSide.data() : stackSide;
  bool allInside = true;
  for (std::size_t k = 0; k < n; ++k) {
    side[k] = normal.dot(polygon[k] - point);
    allInside = allInside && side[k] >= 0;
  }
  out.clear();
  if (allInside) {
    out.assign(polygon.begin(), polygon.end());
    return;
  }
  cutByHeights(
      polygon.data(), side, static_cast<int>(n), [&](const Vec3& p) { out.push_back(p); },
      [](const Vec3&) {});
  if (out.size() < 3) out.clear();
}

Polygon clipToHalfspace(const Polygon& polygon, const Vec3& point, const Vec3& normal) {
  Polygon out;
  clipToHalfspace(polygon, point, normal, out);
  return out;
}

Polygon clipToHalfspaceTwiceOnPlane(const Polygon& polygon, const Vec3& point, const Vec3& normal) {
  Polygon out;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Vec3& a = polygon[k];
    const Vec3& b = polygon[(k + 1) % polygon.size()];
    const double fa = (a - point).dot(normal), fb = (b - point).dot(normal);
    if (fa >= 0) out.push_back(a);
    if ((fa < 0) != (fb < 0)) out.push_back(a + (fa / (fa - fb)) * (b - a));
  }
  return out;
}

}  // namespace rt
