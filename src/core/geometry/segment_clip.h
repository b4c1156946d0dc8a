// Clipping a segment (or a line) to a convex region, Liang and Barsky's way: the region is the intersection
// of half-spaces, each a linear function of the segment's parameter t, f(t) = start + rate t, inside where
// f > 0 (or >= 0), and each narrows the parameter range [t0, t1] to where it holds. One step for every
// caller: a segment against a solid's faces, a source polygon's edges, a mesh cell's edges, an event line
// against a cell.
//
// The conventions:
// - The range narrows at t = -start / rate, from below where rate > 0 and from above where rate < 0; which of
//   f > 0 and f >= 0 holds there does not move the bound.
// - A half-space the segment runs parallel to (|rate| <= `parallel`) keeps the range whole when the segment
//   lies inside it and empties it otherwise; inside is start > 0 for an Open boundary and start >= 0 for a
//   Closed one (a segment along the boundary is kept only by a Closed one).
// - The range is empty once t0 >= t1: a range that narrows to one point is empty.
// Callers that keep a margin put it into `start` (start - tolerance: inside by more than the tolerance).
//
// The callers, and the boundary each keeps as it always has:
//   segmentEntersSolid (quadrature)     Open, margin eps, parallel: rate exactly 0
//   segmentKeepsAPoint (quadrature)     Closed, margin in start, parallel: |rate| <= kTinyRate
//   clipToInterior (contact lines)      Open, margin `tolerance`, parallel: |rate| < kTinyRate
//   segmentCrossesCell (mesher)         Open, margin eps |edge|, parallel: |rate| < kTinyRate, then a
//                                       range longer than 1e-9
//   restrictRange (discontinuities)     Closed on both sides of a slab, parallel: |rate| < kTinyRate
//   chord (exact reference)             Closed, no margin, a line (t unbounded), parallel: rate exactly 0
#pragma once

#include <algorithm>
#include <cmath>

namespace rt {

enum class Boundary : signed char { Open, Closed };

// Narrows [t0, t1] to where start + rate t is inside (above). Returns false when the range is left empty.
inline bool clipRange(double start, double rate, double parallel, Boundary boundary, double& t0, double& t1) {
  if (std::abs(rate) <= parallel) {
    if (boundary == Boundary::Open ? !(start > 0) : !(start >= 0)) return false;
    return t0 < t1;
  }
  const double t = -start / rate;
  if (rate > 0)
    t0 = std::max(t0, t);
  else
    t1 = std::min(t1, t);
  return t0 < t1;
}

// The callers' test for "parallel": rates below 1e-300 in size carry no direction (strictly below, as
// `std::abs(rate) < 1e-300`, is `std::abs(rate) <= kBelowTinyRate`).
inline constexpr double kTinyRate = 1e-300;
inline const double kBelowTinyRate = std::nextafter(kTinyRate, 0.0);

}  // namespace rt
