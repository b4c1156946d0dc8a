#include "core/formfactor/nusselt.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/formfactor/analytic.h"

namespace rt {
namespace {

Vec3 tangentOf(const Vec3& normal) {
  const Vec3 helper = std::abs(normal.x()) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  return normal.cross(helper).normalized();
}

// Walks the projected outline arc by arc, calling visit(pointOnSphere) for every sample (the arc's end
// excluded: it is the next arc's start).
template <typename Visit>
void walkArcs(const Vec3& point, const Vec3* polygon, int count, int segments, Visit&& visit) {
  for (int k = 0; k < count; ++k) {
    const Vec3 a = (polygon[k] - point).normalized();
    const Vec3 b = (polygon[(k + 1) % count] - point).normalized();
    const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
    // Great circle through a and b: a cos t + w sin t with w the unit vector orthogonal to a in their plane.
    Vec3 w = b - a.dot(b) * a;
    const double wn = w.norm();
    for (int s = 0; s < segments; ++s) {
      if (wn == 0) {
        visit(a);
        continue;
      }
      const double t = angle * s / segments;
      visit(Vec3(a * std::cos(t) + (w / wn) * std::sin(t)));
    }
  }
}

}  // namespace

NusseltProjection nusseltProject(const Vec3& point, const Vec3& normal, const Polygon& polygon,
                                 int segmentsPerEdge) {
  NusseltProjection result;
  const Vec3 n = normal.normalized();
  result.u = tangentOf(n);
  result.v = n.cross(result.u);
  if (polygon.size() < 3 || pointToPolygonFormFactor(point, n, polygon) == 0) return result;
  const Polygon visible = clipPolygonToPlane(polygon, point, n);
  const int segments = std::max(1, segmentsPerEdge);
  walkArcs(point, visible.data(), static_cast<int>(visible.size()), segments, [&](const Vec3& s) {
    result.sphereOutline.push_back(s);
    result.diskOutline.emplace_back(s.dot(result.u), s.dot(result.v));
  });
  double twice = 0;
  const std::size_t m = result.diskOutline.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Vec2& p = result.diskOutline[k];
    const Vec2& q = result.diskOutline[(k + 1) % m];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  result.diskArea = 0.5 * std::abs(twice);
  result.formFactor = result.diskArea / std::numbers::pi;
  return result;
}

double nusseltFormFactor(const Vec3& point, const Vec3& normal, const Vec3* polygon, int count,
                         int segmentsPerEdge) {
  if (count < 3 || pointToPolygonFormFactor(point, normal, polygon, count) == 0) return 0;
  // Clip against the tangent plane (same rule as the analytic formula) into a fixed buffer.
  const Polygon source(polygon, polygon + count);
  const Polygon visible = clipPolygonToPlane(source, point, normal);
  const Vec3 u = tangentOf(normal), v = normal.cross(u);
  double twice = 0;
  Vec2 first, previous;
  bool started = false;
  walkArcs(point, visible.data(), static_cast<int>(visible.size()), std::max(1, segmentsPerEdge),
           [&](const Vec3& s) {
             const Vec2 q(s.dot(u), s.dot(v));
             if (started)
               twice += previous.x() * q.y() - q.x() * previous.y();
             else
               first = q, started = true;
             previous = q;
           });
  twice += previous.x() * first.y() - first.x() * previous.y();
  return 0.5 * std::abs(twice) / std::numbers::pi;
}

}  // namespace rt
