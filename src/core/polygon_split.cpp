#include "core/polygon_split.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rt {
namespace {

double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Sign of the turn a -> b -> c, 0 within `eps` (an area tolerance).
int orientation(const Vec2& a, const Vec2& b, const Vec2& c, double eps) {
  const double turn = cross2(b - a, c - b);
  return turn > eps ? 1 : turn < -eps ? -1 : 0;
}

bool onSegment(const Vec2& a, const Vec2& b, const Vec2& p, double eps) {
  return orientation(a, b, p, eps) == 0 &&
         p.x() >= std::min(a.x(), b.x()) - 1e-12 * std::abs(a.x() - b.x()) &&
         p.x() <= std::max(a.x(), b.x()) + 1e-12 * std::abs(a.x() - b.x()) &&
         p.y() >= std::min(a.y(), b.y()) - 1e-12 * std::abs(a.y() - b.y()) &&
         p.y() <= std::max(a.y(), b.y()) + 1e-12 * std::abs(a.y() - b.y());
}

bool segmentsTouch(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double eps) {
  const int o1 = orientation(a, b, c, eps), o2 = orientation(a, b, d, eps);
  const int o3 = orientation(c, d, a, eps), o4 = orientation(c, d, b, eps);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && onSegment(a, b, c, eps)) || (o2 == 0 && onSegment(a, b, d, eps)) ||
         (o3 == 0 && onSegment(c, d, a, eps)) || (o4 == 0 && onSegment(c, d, b, eps));
}

// Area tolerance for turn tests: relative to the outline's extent, so that it works in any unit.
double areaTolerance(const std::vector<Vec2>& outline) {
  Eigen::AlignedBox2d box;
  for (const Vec2& p : outline) box.extend(p);
  const double size = box.diagonal().norm();
  return 1e-12 * size * size;
}

}  // namespace

std::vector<Vec2> projectOntoPlane(const Polygon& polygon, const Vec3& normal) {
  const Vec3 n = normal.normalized();
  // Any unit vector perpendicular to n, then v = n x u: (u, v, n) is right-handed.
  const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = helper.cross(n).normalized();
  const Vec3 v = n.cross(u);
  std::vector<Vec2> out;
  out.reserve(polygon.size());
  for (const Vec3& p : polygon) out.emplace_back((p - polygon[0]).dot(u), (p - polygon[0]).dot(v));
  return out;
}

std::optional<std::pair<int, int>> firstCrossingEdges(const std::vector<Vec2>& outline) {
  const int n = static_cast<int>(outline.size());
  const double eps = areaTolerance(outline);
  for (int k = 0; k < n; ++k)
    for (int m = k + 2; m < n; ++m) {
      if (k == 0 && m == n - 1) continue;  // neighbours through the closing edge
      if (segmentsTouch(outline[k], outline[(k + 1) % n], outline[m], outline[(m + 1) % n], eps))
        return std::make_pair(k, m);
    }
  return std::nullopt;
}

std::optional<std::vector<std::array<int, 3>>> earClip(const std::vector<Vec2>& outline) {
  std::vector<int> left(outline.size());
  for (std::size_t i = 0; i < left.size(); ++i) left[i] = static_cast<int>(i);
  const double eps = areaTolerance(outline);
  std::vector<std::array<int, 3>> triangles;
  // Each pass over the remaining vertices clips at least one; a pass that clips none means no ear exists.
  while (left.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < left.size() && left.size() > 3; ++i) {
      const std::size_t count = left.size();
      const int a = left[(i + count - 1) % count], b = left[i], c = left[(i + 1) % count];
      const int turn = orientation(outline[a], outline[b], outline[c], eps);
      if (turn < 0) continue;  // reflex
      if (turn > 0) {
        bool empty = true;  // no other remaining vertex inside or on the candidate ear
        for (std::size_t k = 0; k < count && empty; ++k) {
          const int p = left[k];
          if (p == a || p == b || p == c) continue;
          // Only a reflex (or flat) vertex can lie in an ear of a simple outline: skip the convex ones.
          if (orientation(outline[left[(k + count - 1) % count]], outline[p], outline[left[(k + 1) % count]],
                          eps) > 0)
            continue;
          if (orientation(outline[a], outline[b], outline[p], eps) >= 0 &&
              orientation(outline[b], outline[c], outline[p], eps) >= 0 &&
              orientation(outline[c], outline[a], outline[p], eps) >= 0) {
            empty = false;
            break;
          }
        }
        if (!empty) continue;
        triangles.push_back({a, b, c});
      }
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
      --i;
    }
    if (!clipped) return std::nullopt;
  }
  if (orientation(outline[left[0]], outline[left[1]], outline[left[2]], eps) > 0)
    triangles.push_back({left[0], left[1], left[2]});
  return triangles;
}

}  // namespace rt
