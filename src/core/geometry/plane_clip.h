// Cutting a convex polygon by a plane (Sutherland and Hodgman's step), one routine for every caller: the
// shadow clipper's cones, the horizon clips of Lambert's formula and of the exact reference, the 2D cells
// of the discontinuity mesher.
//
// The conventions, the same for every caller:
// - A corner's height is n . (p - origin), in units of the normal's length (n need not be unit). Each caller
//   snaps the heights within its own tolerance to exactly 0 first (the tolerance is said at each function).
// - A corner of height >= 0 belongs to the front part, one of height <= 0 to the back part: a corner on the
//   plane belongs to both, once.
// - An edge adds its crossing only where its ends lie strictly on opposite sides, at
//   p + (q - p) (h_p / (h_p - h_q)), to both parts; an edge that only touches the plane adds nothing.
// - A part of fewer than 3 corners is empty (count 0, or a cleared vector).
//
// The tolerances, each the caller's own and kept as it always was:
//   splitByPlane (shadow clipper's cones, event cells, probes)  d^2 <= margin2, i.e. |d| <= eps |n|
//   clipToFront (occluders, sources and receivers)               |d| <= eps |n|; nothing in front: empty
//   clipPolygonToPlane (analytic.h, Lambert's horizon clip)      |d| <= 1e-12 of the corners' distance
//                                                                from the origin, times |n|
//   clipToHalfspace (exact reference)                            none; nothing behind: kept whole
//   the hemicube's frustum, the mesher's 2D cells, a block's     none
//   umbra (block_shadow_regions)
//   clipToHalfspaceTwiceOnPlane (contact lines)                  none, and its own crossing rule (below)
#pragma once

#include <type_traits>
#include <vector>

#include "core/geometry/convex_polygon.h"

namespace rt {

// The walk itself, for callers that carry more than a point per corner: for k = 0 .. count-1, corner(k),
// then, where the edge from k to next = k + 1 (mod count) crosses strictly, crossing(k, next, t) with
// t = h[k] / (h[k] - h[next]) the crossing's place along the edge.
template <class Corner, class Crossing>
inline void walkHeights(const double* h, int count, Corner&& corner, Crossing&& crossing) {
  for (int k = 0; k < count; ++k) {
    const int next = (k + 1) % count;
    const double hp = h[k], hq = h[next];
    corner(k);
    if ((hp > 0 && hq < 0) || (hp < 0 && hq > 0)) crossing(k, next, hp / (hp - hq));
  }
}

// The cut of the corners `in` (2D or 3D points) with heights `h`: front(p) receives the front part's
// corners in order, back(p) the back part's (either may ignore them).
template <class Point, class Front, class Back>
inline void cutByHeights(const Point* in, const double* h, int count, Front&& front, Back&& back) {
  walkHeights(
      h, count,
      [&](int k) {
        if (h[k] >= 0) front(in[k]);
        if (h[k] <= 0) back(in[k]);
      },
      [&](int k, int next, double t) {
        const Point cut = in[k] + (in[next] - in[k]) * t;
        front(cut);
        back(cut);
      });
}

namespace plane_clip_detail {
// Room for n heights past the stack arrays of the hot loops (ConvexPolygon::kInline of them): kept per
// thread and per `Site`, a caller's own, so that two clips in flight never share one. (A SmallBuffer would
// put an object with a destructor in the clipper's innermost loop.)
template <int Site>
double* spilledHeights(int n) {
  thread_local std::vector<double> heights;
  if (static_cast<int>(heights.size()) < n) heights.resize(static_cast<std::size_t>(n));
  return heights.data();
}
}  // namespace plane_clip_detail

// Splits `in` by the plane through `origin` with normal `normal`; corners whose height d has
// d^2 <= `margin2` count as on it (margin2 = eps^2 |normal|^2 for a margin eps in lengths: no square root of
// the normal's length per plane). Returns 1 when no corner lies behind (nothing written: a polygon wholly
// on the plane, or a normal of no length, is in front), -1 when none lies in front (nothing written), 0
// when both do: then the part in front goes to `front` and, where `back` is given, the part behind to it.
template <class Buffer>
inline int splitByPlane(const BasicConvexPolygon<Buffer>& in, const Vec3& origin, const Vec3& normal,
                        double margin2, BasicConvexPolygon<Buffer>& front,
                        std::type_identity_t<BasicConvexPolygon<Buffer>>* back) {
  constexpr int kStack = BasicConvexPolygon<Buffer>::kInline;
  double local[kStack];
  double* side = in.count <= kStack ? local : plane_clip_detail::spilledHeights<0>(in.count);
  bool anyBehind = false, anyFront = false;
  for (int k = 0; k < in.count; ++k) {
    double d = normal.dot(in.v[static_cast<std::size_t>(k)] - origin);
    if (d * d <= margin2) d = 0;
    side[k] = d;
    anyBehind |= d < 0;
    anyFront |= d > 0;
  }
  if (!anyBehind) return 1;
  if (!anyFront) return -1;
  // Each corner adds itself and a cut at most, whatever rounding says of the sides.
  front.v.reserve(2 * in.count);
  front.count = 0;
  if (back) {
    back->v.reserve(2 * in.count);
    back->count = 0;
  }
  cutByHeights(
      in.data(), side, in.count, [&](const Vec3& p) { front.v[static_cast<std::size_t>(front.count++)] = p; },
      [&](const Vec3& p) {
        if (back) back->v[static_cast<std::size_t>(back->count++)] = p;
      });
  if (front.count < 3) front.count = 0;
  if (back && back->count < 3) back->count = 0;
  return 0;
}

// The part of the corners `in` with normal . (p - origin) >= 0, corners within `eps` (a length) of the plane
// counting as on it, into `out`. Empty (count 0) when less than a triangle is left, when no corner lies in
// front (a polygon wholly on the plane is dropped) and for a normal of no length. Returns whether `in` was
// kept whole (nothing of it behind), `out` then a copy.
bool clipToFront(const Vec3* in, int count, const Vec3& origin, const Vec3& normal, double eps,
                 ConvexPolygon& out);

// The part of `polygon` with normal . (p - point) >= 0, with no tolerance: a corner is on the plane only at
// height exactly 0. Unlike clipToFront(), a polygon with no corner behind is kept whole even when it lies
// wholly on the plane (the exact reference's convention: its callers clip domains that may lie in the
// plane). Empty when less than a triangle is left. Into `out`, reusing its storage.
void clipToHalfspace(const Polygon& polygon, const Vec3& point, const Vec3& normal, Polygon& out);
Polygon clipToHalfspace(const Polygon& polygon, const Vec3& point, const Vec3& normal);

// The part of `polygon` with normal . (p - point) >= 0, with no tolerance, by the one other convention: an
// edge adds a crossing wherever one end is behind (height < 0) and the other not, so that a corner exactly
// on the plane next to one behind comes out twice (itself, and the crossing at it or within rounding of
// it). The meshes cut along contact lines (contact_lines.h) are made so; their pieces become elements, so
// this stays as it is rather than change those meshes and their form factors. Not emptied below 3 corners
// (its caller drops those).
Polygon clipToHalfspaceTwiceOnPlane(const Polygon& polygon, const Vec3& point, const Vec3& normal);

}  // namespace rt
