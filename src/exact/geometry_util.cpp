#include "exact/geometry_util.h"

#include <algorithm>
#include <limits>

namespace rt::exact {

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
