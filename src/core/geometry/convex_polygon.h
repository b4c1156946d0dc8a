// A convex polygon: its corners in order (counter-clockwise seen from the side it faces) and their count,
// held in a buffer chosen by what makes the polygon. One template, so that every polygon of the form-factor
// methods has the same measures:
//
// - ConvexPolygon: 32 corners inline and more on the heap when reserved (small_buffer.h). Occluders, clipped
//   pieces and mesh elements, whose corner count a cut or an input can raise.
// - FixedConvexPolygon<N>: N corners and never more (fixed_buffer.h); asking for more fails with
//   CheckFailure. Quadrature panels (3 or 4 corners), copied by the million.
//
// Writers reserve() the corners they will write, then set v[k] and count. The measures read the first
// `count` corners only.
#pragma once

#include <algorithm>
#include <initializer_list>
#include <vector>

#include "core/geometry/fixed_buffer.h"
#include "core/geometry/small_buffer.h"
#include "core/vec.h"

namespace rt {

// Newell's sum of v[k] x v[k+1]: for a planar polygon twice its area times its unit normal (the normal the
// corner order turns about), whatever the corner count.
inline Vec3 twiceAreaVector(const Vec3* v, int count) {
  Vec3 sum = Vec3::Zero();
  for (int k = 0; k < count; ++k) sum += v[k].cross(v[(k + 1) % count]);
  return sum;
}

// The mean of the corners (not the area centroid; core/polygon.h has that); the origin for no corners.
inline Vec3 cornerMean(const Vec3* v, int count) {
  Vec3 sum = Vec3::Zero();
  for (int k = 0; k < count; ++k) sum += v[k];
  return sum / std::max(1, count);
}

template <class Buffer>
struct BasicConvexPolygon {
  static constexpr int kInline = Buffer::kInline;
  Buffer v;
  int count = 0;

  BasicConvexPolygon() = default;
  BasicConvexPolygon(std::initializer_list<Vec3> corners) {
    assign(corners.begin(), static_cast<int>(corners.size()));
  }

  Vec3* data() { return v.data(); }
  const Vec3* data() const { return v.data(); }
  void reserve(int n) { v.reserve(n); }
  // The corners of another polygon (only those in use: a whole copy of the buffer costs more than a clip).
  void assign(const Vec3* corners, int n) {
    v.reserve(n);
    std::copy_n(corners, n, v.data());
    count = n;
  }
  template <class Other>
  void assign(const BasicConvexPolygon<Other>& other) {
    assign(other.data(), other.count);
  }

  double area() const { return 0.5 * twiceAreaVector(data(), count).norm(); }
  Vec3 centre() const { return cornerMean(data(), count); }
  // Largest distance from centre() to a corner.
  double radius() const {
    const Vec3 c = centre();
    double r = 0;
    for (int k = 0; k < count; ++k) r = std::max(r, (v[static_cast<std::size_t>(k)] - c).norm());
    return r;
  }
  double longestEdge() const {
    double h = 0;
    for (int k = 0; k < count; ++k)
      h = std::max(h, (v[static_cast<std::size_t>((k + 1) % count)] - v[static_cast<std::size_t>(k)]).norm());
    return h;
  }
  Polygon toPolygon() const { return Polygon(data(), data() + count); }
};

using ConvexPolygon = BasicConvexPolygon<SmallBuffer<Vec3, 32>>;
template <int N>
using FixedConvexPolygon = BasicConvexPolygon<FixedBuffer<Vec3, N>>;

}  // namespace rt
