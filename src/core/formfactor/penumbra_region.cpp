#include "core/formfactor/penumbra_region.h"

#include <algorithm>
#include <cmath>

namespace rt {
namespace {

double cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

}  // namespace

bool PenumbraRegion::build(const Vec3* corners, int cornerCount, const Vec3* receiver, int receiverCount,
                           const Vec3& origin, const Vec3& normal, double eps) {
  hull_.clear();
  origin_ = origin;
  u_ = normal.unitOrthogonal();
  v_ = normal.cross(u_);
  eps_ = eps;
  double lowest = INFINITY;
  for (int r = 0; r < receiverCount; ++r) lowest = std::min(lowest, normal.dot(receiver[r] - origin));
  std::vector<Eigen::Vector2d> points;
  points.reserve(static_cast<std::size_t>(cornerCount * receiverCount));
  for (int c = 0; c < cornerCount; ++c) {
    const double h = normal.dot(corners[c] - origin);
    if (h < -eps || !(h < lowest - eps)) return false;
    for (int r = 0; r < receiverCount; ++r) {
      const double hr = normal.dot(receiver[r] - origin);
      const Vec3 x = receiver[r] + (corners[c] - receiver[r]) * (hr / (hr - h));
      points.push_back({u_.dot(x - origin), v_.dot(x - origin)});
    }
  }
  // Andrew's monotone chain.
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t h = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    while (h >= 2 && cross2(hull[h - 2], hull[h - 1], points[k]) <= 0) --h;
    hull[h++] = points[k];
  }
  for (std::size_t k = points.size() - 1, lower = h + 1; k-- > 0;) {
    while (h >= lower && cross2(hull[h - 2], hull[h - 1], points[k]) <= 0) --h;
    hull[h++] = points[k];
  }
  if (h < 4) return false;  // fewer than three corners: a degenerate region, left to the hull test
  hull_.assign(hull.begin(), hull.begin() + static_cast<std::ptrdiff_t>(h - 1));
  return true;
}

bool PenumbraRegion::meets(const Vec3* polygon, int count) const {
  if (hull_.empty()) return true;
  Eigen::Vector2d flat[8];
  if (count > 8) return true;
  for (int k = 0; k < count; ++k) flat[k] = {u_.dot(polygon[k] - origin_), v_.dot(polygon[k] - origin_)};
  // Separating axes: the edges of either convex polygon.
  auto separates = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d* points,
                       int n, double sign) {
    const Eigen::Vector2d edge = b - a;
    const double margin = eps_ * edge.norm();
    for (int k = 0; k < n; ++k)
      if (sign * (edge.x() * (points[k] - a).y() - edge.y() * (points[k] - a).x()) >= -margin) return false;
    return true;
  };
  const int m = static_cast<int>(hull_.size());
  for (int k = 0; k < m; ++k)
    if (separates(hull_[static_cast<std::size_t>(k)], hull_[static_cast<std::size_t>((k + 1) % m)], flat,
                  count, 1.0))
      return false;
  // The polygon's orientation in the plane's frame decides which side of its edges is outside.
  double twice = 0;
  for (int k = 0; k < count; ++k)
    twice += flat[k].x() * flat[(k + 1) % count].y() - flat[(k + 1) % count].x() * flat[k].y();
  const double sign = twice >= 0 ? 1.0 : -1.0;
  for (int k = 0; k < count; ++k)
    if (separates(flat[k], flat[(k + 1) % count], hull_.data(), m, sign)) return false;
  return true;
}

}  // namespace rt
