// F(dA at x -> visible part of the receiver) for one pair. A double-precision filter classifies each occluder
// with a safety margin: clearly outside the pyramid from x over the receiver (ignored), or clearly covering
// the whole pyramid (F = 0); the filter never decides a case it cannot prove with its margin. The occluders
// it cannot decide cut the receiver: either by CGAL's exact projection and 2D Booleans (Booleans::Exact), or
// by splitting the receiver into convex pieces along the planes of their shadow volumes in double precision
// (Booleans::Split), whose only error is rounding of the piece boundaries (~1e-16 relative), about a thousand
// times faster.
#pragma once

#include "exact/exact_reference.h"
#include "exact/shaft.h"

namespace rt::exact {

class PointEvaluator {
 public:
  PointEvaluator(const PairGeometry& pair, Booleans booleans) : pair_(pair), booleans_(booleans) {}
  double operator()(const Vec3& x) const;
  long exactEvaluations() const { return exactEvaluations_; }
  long splitEvaluations() const { return splitEvaluations_; }
  long evaluations() const { return evaluations_; }

 private:
  const PairGeometry& pair_;
  Booleans booleans_;
  mutable long exactEvaluations_ = 0;  // one evaluator per pair and thread: no atomics needed
  mutable long splitEvaluations_ = 0;
  mutable long evaluations_ = 0;
};

}  // namespace rt::exact
