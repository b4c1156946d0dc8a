// An axis-aligned box as a scene gives one: six faces, counter-clockwise seen from outside, and what the
// quadrature method derives from them (outward planes, the solid's shape, a point inside). Shared by the
// shadow clipper's tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

#include "core/formfactor/quadrature/closed_solids.h"
#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/quadrature/solid_silhouette.h"

namespace rt {

// A ConvexPolygon from its corners.
inline ConvexPolygon polygon(std::initializer_list<Vec3> corners) {
  ConvexPolygon p;
  p.v.reserve(static_cast<int>(corners.size()));
  for (const Vec3& c : corners) p.v[static_cast<std::size_t>(p.count++)] = c;
  return p;
}

struct Box {
  std::vector<std::vector<Vec3>> faces;
  SolidPlanes planes;  // per face: outward unit normal, offset
  Vec3 centre;
  std::vector<SolidShape> shapes;  // one: this box's faces, corners and edges
  // The faces as occluders bounding solid 0.
  std::vector<OccluderPolygon> occluders() const {
    std::vector<OccluderPolygon> out;
    for (const auto& face : faces) out.push_back({&face, 0});
    return out;
  }
};

inline Box box(const Vec3& lo, const Vec3& hi) {
  Box b;
  b.centre = 0.5 * (lo + hi);
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Vec3 normal = Vec3::Zero();
      normal[axis] = side ? 1 : -1;
      std::vector<Vec3> face;
      for (const auto& [a, c] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
        Vec3 corner;
        corner[axis] = side ? hi[axis] : lo[axis];
        corner[u] = a ? hi[u] : lo[u];
        corner[v] = c ? hi[v] : lo[v];
        face.push_back(corner);
      }
      if ((face[1] - face[0]).cross(face[2] - face[1]).dot(normal) < 0)
        std::reverse(face.begin(), face.end());
      b.faces.push_back(face);
      b.planes.push_back({normal, normal.dot(face[0])});
    }
  std::vector<const std::vector<Vec3>*> outlines;
  for (const auto& face : b.faces) outlines.push_back(&face);
  b.shapes = solidShapes(outlines, std::vector<int>(b.faces.size(), 0), 1);
  return b;
}

// Whether the segment pq meets the axis-aligned box [lo, hi] (slabs): the brute-force reference of the
// tests that prove a block hides nothing or all of a pair.
inline bool segmentMeetsBox(const Vec3& p, const Vec3& q, const Vec3& lo, const Vec3& hi) {
  double t0 = 0, t1 = 1;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = q[axis] - p[axis];
    if (std::abs(d) < 1e-15) {
      if (p[axis] < lo[axis] || p[axis] > hi[axis]) return false;
      continue;
    }
    double a = (lo[axis] - p[axis]) / d, b = (hi[axis] - p[axis]) / d;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

// Whether some segment between grids of points (steps x steps each, bilinear over the corners 0..3) on two
// quadrilaterals meets the box: what a proof that a block misses a pair is checked against.
inline bool someSegmentMeetsBox(const ConvexPolygon& a, const ConvexPolygon& b, const Vec3& lo,
                                const Vec3& hi, int steps) {
  auto at = [](const ConvexPolygon& q, double s, double t) {
    return Vec3((1 - s) * ((1 - t) * q.v[0] + t * q.v[3]) + s * ((1 - t) * q.v[1] + t * q.v[2]));
  };
  for (int s = 0; s <= steps; ++s)
    for (int t = 0; t <= steps; ++t)
      for (int u = 0; u <= steps; ++u)
        for (int v = 0; v <= steps; ++v)
          if (segmentMeetsBox(at(a, double(s) / steps, double(t) / steps),
                              at(b, double(u) / steps, double(v) / steps), lo, hi))
            return true;
  return false;
}

}  // namespace rt
