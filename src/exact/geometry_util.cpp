#include "exact/geometry_util.h"

#include <algorithm>
#include <limits>

namespace rt::exact {

Polygon clipToHalfspace(const Polygon& polygon, const Vec3& point, const Vec3& normal) {
  Polygon out;
  clipToHalfspace(polygon, point, normal, out);
  return out;
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
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t l = (k + 1) % n;
    if (side[k] >= 0) out.push_back(polygon[k]);
    if ((side[k] > 0 && side[l] < 0) || (side[k] < 0 && side[l] > 0)) {
      const double t = side[k] / (side[k] - side[l]);
      out.push_back(polygon[k] + t * (polygon[l] - polygon[k]));
    }
  }
  if (out.size() < 3) out.clear();
}

Eigen::AlignedBox3d boundsOf(const Polygon& polygon) {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : polygon) box.extend(v);
  return box;
}

std::pair<double, double> distanceRange(const Polygon& polygon, const Vec3& point, const Vec3& normal) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec3& v : polygon) {
    const double d = normal.dot(v - point);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return {lo, hi};
}

}  // namespace rt::exact
