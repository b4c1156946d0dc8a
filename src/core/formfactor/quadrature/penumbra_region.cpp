#include "core/formfactor/quadrature/penumbra_region.h"

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
  count_ = 0;
  if (cornerCount * receiverCount > kMaxPoints || receiverCount > 8) return false;
  origin_ = origin;
  u_ = normal.unitOrthogonal();
  v_ = normal.cross(u_);
  eps_ = eps;
  double heights[8];
  double lowest = INFINITY;
  for (int r = 0; r < receiverCount; ++r) {
    heights[r] = normal.dot(receiver[r] - origin);
    lowest = std::min(lowest, heights[r]);
  }
  std::array<Eigen::Vector2d, kMaxPoints> points;
  int n = 0;
  for (int c = 0; c < cornerCount; ++c) {
    const double h = normal.dot(corners[c] - origin);
    if (h < -eps || !(h < lowest - eps)) return false;
    for (int r = 0; r < receiverCount; ++r) {
      const Vec3 x = receiver[r] + (corners[c] - receiver[r]) * (heights[r] / (heights[r] - h)) - origin;
      points[static_cast<std::size_t>(n++)] = {u_.dot(x), v_.dot(x)};
    }
  }
  const int hullCount = convexHull2d(points.data(), n, hull_.data());
  if (hullCount < 3) return false;  // fewer than three corners: a degenerate region, left to the hull test
  count_ = hullCount;
  for (int k = 0; k < count_; ++k)
    margin2_[static_cast<std::size_t>(k)] =
        eps * eps *
        (hull_[static_cast<std::size_t>((k + 1) % count_)] - hull_[static_cast<std::size_t>(k)])
            .squaredNorm();
  return true;
}

int convexHull2d(Eigen::Vector2d* points, int n, Eigen::Vector2d* out) {
  if (n > kMaxHullPoints) return 0;
  // Andrew's monotone chain (at most n + 1 entries while it runs: the last repeats the first).
  std::sort(points, points + n, [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::array<Eigen::Vector2d, kMaxHullPoints + 1> chain;
  int h = 0;
  for (int k = 0; k < n; ++k) {
    while (h >= 2 && cross2(chain[static_cast<std::size_t>(h - 2)], chain[static_cast<std::size_t>(h - 1)],
                            points[k]) <= 0)
      --h;
    chain[static_cast<std::size_t>(h++)] = points[k];
  }
  for (int k = n - 1, lower = h + 1; k-- > 0;) {
    while (h >= lower && cross2(chain[static_cast<std::size_t>(h - 2)],
                                chain[static_cast<std::size_t>(h - 1)], points[k]) <= 0)
      --h;
    chain[static_cast<std::size_t>(h++)] = points[k];
  }
  if (h < 4) return 0;
  std::copy(chain.begin(), chain.begin() + (h - 1), out);
  return h - 1;
}
bool PenumbraRegion::meets(const Vec3* polygon, int count) const {
  if (count_ == 0) return true;
  Eigen::Vector2d flat[8];
  if (count > 8) return true;
  for (int k = 0; k < count; ++k) flat[k] = {u_.dot(polygon[k] - origin_), v_.dot(polygon[k] - origin_)};
  // Separating axes: the edges of either convex polygon.
  auto separates = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d* points,
                       int n, double sign, double margin2) {
    const Eigen::Vector2d edge = b - a;
    for (int k = 0; k < n; ++k) {
      // Negative beyond the edge; separated only beyond eps |edge| (compared squared: no root per edge).
      const double side = sign * (edge.x() * (points[k] - a).y() - edge.y() * (points[k] - a).x());
      if (side >= 0 || side * side <= margin2) return false;
    }
    return true;
  };
  const int m = count_;
  for (int k = 0; k < m; ++k)
    if (separates(hull_[static_cast<std::size_t>(k)], hull_[static_cast<std::size_t>((k + 1) % m)], flat,
                  count, 1.0, margin2_[static_cast<std::size_t>(k)]))
      return false;
  // The polygon's orientation in the plane's frame decides which side of its edges is outside.
  double twice = 0;
  for (int k = 0; k < count; ++k)
    twice += flat[k].x() * flat[(k + 1) % count].y() - flat[(k + 1) % count].x() * flat[k].y();
  const double sign = twice >= 0 ? 1.0 : -1.0;
  for (int k = 0; k < count; ++k)
    if (separates(flat[k], flat[(k + 1) % count], hull_.data(), m, sign,
                  eps_ * eps_ * (flat[(k + 1) % count] - flat[k]).squaredNorm()))
      return false;
  return true;
}

}  // namespace rt
