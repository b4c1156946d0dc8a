#include "core/refine/constrained_triangulation.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "core/geometry/plane_clip.h"
#include "core/geometry/segment_clip.h"

namespace rt {
namespace {

struct Registered {
  std::mutex mutex;
  ConstrainedTriangulator triangulator = cutConvexDomain;
  std::string name = "convex cuts";
};

Registered& registered() {
  static Registered r;
  return r;
}

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Splits a convex cell by the line through p with direction d; returns false when the line misses its
// interior.
bool splitCell(const std::vector<Vec2>& cell, const Vec2& p, const Vec2& d, double eps,
               std::vector<Vec2>& left, std::vector<Vec2>& right) {
  left.clear();
  right.clear();
  const std::size_t n = cell.size();
  bool anyLeft = false, anyRight = false;
  for (std::size_t k = 0; k < n; ++k) {
    const double s = cross(d, cell[k] - p);
    anyLeft |= s > eps;
    anyRight |= s < -eps;
  }
  if (!anyLeft || !anyRight) return false;
  // Cut with no tolerance (plane_clip.h): the margin only decided above that both sides have area.
  std::vector<double> heights(n);
  for (std::size_t k = 0; k < n; ++k) heights[k] = cross(d, cell[k] - p);
  cutByHeights(
      cell.data(), heights.data(), static_cast<int>(n), [&](const Vec2& x) { left.push_back(x); },
      [&](const Vec2& x) { right.push_back(x); });
  return left.size() >= 3 && right.size() >= 3;
}

// Does the open segment p-q pass through the interior of the convex cell?
bool segmentCrossesCell(const std::vector<Vec2>& cell, const Vec2& p, const Vec2& q, double eps) {
  double t0 = 0, t1 = 1;
  const Vec2 d = q - p;
  for (std::size_t k = 0; k < cell.size(); ++k) {
    const Vec2 e = cell[(k + 1) % cell.size()] - cell[k];
    // inside: cross(e, x - a) > eps
    const double f0 = cross(e, p - cell[k]) - eps * e.norm();
    if (!clipRange(f0, cross(e, d), kBelowTinyRate, Boundary::Open, t0, t1)) return false;
  }
  return t1 - t0 > 1e-9;
}

}  // namespace

void setConstrainedTriangulator(ConstrainedTriangulator triangulator, const std::string& name) {
  std::lock_guard<std::mutex> lock(registered().mutex);
  registered().triangulator = std::move(triangulator);
  registered().name = name;
}

ConstrainedTriangulator constrainedTriangulator() {
  std::lock_guard<std::mutex> lock(registered().mutex);
  return registered().triangulator;
}

std::string constrainedTriangulatorName() {
  std::lock_guard<std::mutex> lock(registered().mutex);
  return registered().name;
}

PlanarTriangulation cutConvexDomain(const PlanarDomain& domain) {
  double size = 0;
  for (const Vec2& a : domain.boundary)
    for (const Vec2& b : domain.boundary) size = std::max(size, (a - b).norm());
  const double eps = 1e-9 * size;
  std::vector<std::vector<Vec2>> cells{domain.boundary};
  std::vector<Vec2> left, right;
  for (const auto& [p, q] : domain.constraints) {
    if ((q - p).norm() <= eps) continue;
    std::vector<std::vector<Vec2>> next;
    for (const auto& cell : cells) {
      if (segmentCrossesCell(cell, p, q, eps) && splitCell(cell, p, (q - p).normalized(), eps, left, right)) {
        next.push_back(left);
        next.push_back(right);
      } else {
        next.push_back(cell);
      }
    }
    cells = std::move(next);
  }
  PlanarTriangulation out;
  for (const auto& cell : cells)
    for (std::size_t k = 1; k + 1 < cell.size(); ++k) {
      const Vec2 a = cell[0], b = cell[k], c = cell[k + 1];
      const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
      const int n =
          domain.maxEdge > 0 ? std::max(1, static_cast<int>(std::ceil(longest / domain.maxEdge - 1e-9))) : 1;
      auto at = [&](int i, int j) { return Vec2(a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n)); };
      auto add = [&](const Vec2& x, const Vec2& y, const Vec2& z) {
        const int base = static_cast<int>(out.points.size());
        out.points.insert(out.points.end(), {x, y, z});
        out.triangles.push_back({base, base + 1, base + 2});
      };
      for (int j = 0; j < n; ++j)
        for (int i = 0; i + j < n; ++i) {
          add(at(i, j), at(i + 1, j), at(i, j + 1));
          if (i + j + 1 < n) add(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
        }
    }
  return out;
}

}  // namespace rt
