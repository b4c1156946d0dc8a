// F(dA at x -> visible part of the receiver) for one pair. A double-precision filter classifies each occluder
// with a safety margin: clearly outside the pyramid from x over the receiver (ignored), or clearly covering
// the whole pyramid (F = 0); the filter never decides a case it cannot prove with its margin. The occluders
// it cannot decide cut the receiver: either by CGAL's exact projection and 2D Booleans (Booleans::Exact), or
// by splitting the receiver into convex pieces along the planes of their shadow volumes in double precision
// (Booleans::Split), whose only error is rounding of the piece boundaries (~1e-16 relative), about a thousand
// times faster.
//
// Everything that does not depend on x is prepared once per pair (the source is planar, so the receiver's
// horizon clip is the same for every x), and the per-point work reuses its buffers: an evaluator belongs to
// one pair and one thread.
#pragma once

#include <vector>

#include "exact/exact_reference.h"
#include "exact/shaft.h"

namespace rt::exact {

class PointEvaluator {
 public:
  PointEvaluator(const PairGeometry& pair, Booleans booleans);
  double operator()(const Vec3& x) const;
  // The same without any occluder: F(dA at x -> horizon-clipped receiver). operator() returns exactly this
  // number wherever no occluder is in the way, so their difference is exactly 0 there.
  double unoccluded(const Vec3& x) const;
  long exactEvaluations() const { return exactEvaluations_; }
  long splitEvaluations() const { return splitEvaluations_; }
  long evaluations() const { return evaluations_; }

 private:
  struct Occluder {
    const Polygon* polygon;     // as culled by the shaft
    Vec3 normal;                // unit; zero for a degenerate polygon
    std::vector<Vec3> inward;   // unit in-plane normals of its edges, pointing inside (zero: degenerate edge)
    Polygon inFrontOfReceiver;  // clipped to the receiver's front half-space (what can cast a shadow)
  };
  enum class Relation { Outside, Covers, Unknown };
  Relation classify(const Occluder& occluder, const Vec3& x, double eps) const;
  // Removes the shadow of one occluder from x from the pieces in work_ (count: pieceCount_).
  void subtractShadow(const Vec3& x, const Occluder& occluder, double eps, double minArea) const;

  const PairGeometry& pair_;
  Booleans booleans_;
  Polygon receiver_;  // clipped to the source's front half-space (horizon clipping)
  double receiverArea_ = 0;
  std::vector<Occluder> occluders_;
  mutable std::vector<Vec3> cone_;  // per-point scratch: inward normals of the pyramid from x over receiver_
  mutable std::vector<const Occluder*> uncertain_;
  mutable std::vector<Polygon> work_, next_;
  mutable std::size_t pieceCount_ = 0;
  mutable Polygon clipped_, inside_, outside_;
  mutable long exactEvaluations_ = 0;  // one evaluator per pair and thread: no atomics needed
  mutable long splitEvaluations_ = 0;
  mutable long evaluations_ = 0;
};

}  // namespace rt::exact
