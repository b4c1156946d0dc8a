// Small helpers shared by the shadow clipper's two files (shadow_clipper.cpp: clipping; shadow_proofs.cpp:
// the proofs that a receiver is wholly hidden and the probes for shadows the samples miss).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/formfactor/quadrature/shadow_clipper.h"

namespace rt::shadow_detail {

inline Vec3 centreOf(const SmallPolygon& p) {
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < p.count; ++k) c += p.v[static_cast<std::size_t>(k)];
  return c / std::max(1, p.count);
}

inline Vec3 centreOf(const Vec3* p, int n) {
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < n; ++k) c += p[k];
  return c / std::max(1, n);
}

// The faces of the convex hull of two convex polygons other than their own planes each hold an edge of one
// and a corner of the other. Calls visit(p, n, margin2) for every plane through an edge of `edges` (p its
// first corner) and a corner of `others`, n its normal unnormalised and margin2 = eps^2 |n|^2 (a height d is
// beyond eps when d^2 > margin2: no square root for the many planes rejected), until visit returns true;
// returns whether it did. All of `edges` lies on the side of its own centre of each such plane.
template <class Visit>
bool forEachEdgeCornerPlane(const Vec3* edges, int ne, const Vec3* others, int no, double eps,
                            Visit&& visit) {
  for (int e = 0; e < ne; ++e) {
    const Vec3& p = edges[e];
    const Vec3 edge = edges[(e + 1) % ne] - p;
    for (int k = 0; k < no; ++k) {
      const Vec3 n = edge.cross(others[k] - p);
      const double length2 = n.squaredNorm();
      if (!(length2 > 0)) continue;
      if (visit(p, n, eps * eps * length2)) return true;
    }
  }
  return false;
}

// Room for n heights of a clip's corners past the stack array the hot loops use (SmallPolygon::kInline
// of them): kept per thread and per `Site`, a caller's own, so that two clips in flight never share one. (A
// SmallBuffer would put an object with a destructor in the clipper's innermost loop.)
template <int Site>
double* spilledHeights(int n) {
  thread_local std::vector<double> heights;
  if (static_cast<int>(heights.size()) < n) heights.resize(static_cast<std::size_t>(n));
  return heights.data();
}

// Only the corners in use: a SmallPolygon holds room for 32, and whole copies cost more than the clipping.
inline void copyPolygon(const SmallPolygon& from, SmallPolygon& to) {
  to.v.reserve(from.count);
  to.count = from.count;
  std::copy_n(from.v.begin(), from.count, to.v.begin());
}

// Splits `in` by the plane through `origin` with normal `normal`, corners whose height d above it (in units
// of the normal's length) has d^2 <= `margin2` counting as on it: the margin squared, so that callers need no
// square root of the normal's length. Returns 1 when no corner lies behind (nothing written), -1 when none
// lies in front (nothing written), 0 when both do: then the part in front goes to `front` and, where `back`
// is given, the part behind to it. In one pass, as the shadow cut of each piece by each side plane of a cone
// needs both parts.
inline int splitAt(const SmallPolygon& in, const Vec3& origin, const Vec3& normal, double margin2,
                   SmallPolygon& front, SmallPolygon* back) {
  double local[SmallPolygon::kInline];
  double* side = in.count <= SmallPolygon::kInline ? local : spilledHeights<0>(in.count);
  bool anyBehind = false, anyFront = false;
  for (int k = 0; k < in.count; ++k) {
    double d = normal.dot(in.v[static_cast<std::size_t>(k)] - origin);
    if (d * d <= margin2) d = 0;
    side[k] = d;
    anyBehind |= d < 0;
    anyFront |= d > 0;
  }
  if (!anyBehind) return 1;  // (a piece wholly on the plane, or a plane of no direction, cuts nothing)
  if (!anyFront) return -1;
  // Each corner adds itself and a cut at most, whatever rounding says of the sides.
  front.v.reserve(2 * in.count);
  front.count = 0;
  if (back) {
    back->v.reserve(2 * in.count);
    back->count = 0;
  }
  for (int k = 0; k < in.count; ++k) {
    const int next = (k + 1) % in.count;
    const double dp = side[k], dq = side[next];
    const Vec3& p = in.v[static_cast<std::size_t>(k)];
    if (dp >= 0) front.v[static_cast<std::size_t>(front.count++)] = p;
    if (back && dp <= 0) back->v[static_cast<std::size_t>(back->count++)] = p;
    if ((dp > 0 && dq < 0) || (dp < 0 && dq > 0)) {
      const Vec3 cut = p + (in.v[static_cast<std::size_t>(next)] - p) * (dp / (dp - dq));
      front.v[static_cast<std::size_t>(front.count++)] = cut;
      if (back) back->v[static_cast<std::size_t>(back->count++)] = cut;
    }
  }
  if (front.count < 3) front.count = 0;
  if (back && back->count < 3) back->count = 0;
  return 0;
}

}  // namespace rt::shadow_detail
