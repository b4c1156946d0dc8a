// Deterministic random numbers and stratified points on elements for the stochastic form-factor methods.
// Every element pair gets its own generator seeded from (seed, i, j), so results do not depend on thread
// scheduling.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec.h"

namespace rt {

// SplitMix64: tiny, fast, statistically fine for sampling, and trivially seedable per pair.
class PairRandom {
 public:
  PairRandom(std::uint64_t seed, std::uint64_t i, std::uint64_t j);
  std::uint64_t next();
  double uniform();  // in [0, 1)

 private:
  std::uint64_t state_;
};

// Sample k of n of a jittered grid over [0,1]^2: stratified, so errors fall faster than 1/sqrt n for smooth
// integrands. The grid has floor(sqrt n) columns and as many full rows as n fills; the samples left over
// (n not a product of the two) are uniform over the square, so every n is unbiased (a partly filled last row
// would leave part of the square unsampled).
Vec2 jitteredSample(int k, int n, PairRandom& random);

// The same grid with its shape worked out once, for loops that draw many samples of one n.
class StrataGrid {
 public:
  explicit StrataGrid(int n);
  Vec2 sample(int k, PairRandom& random) const;

 private:
  int columns_, rows_;
};

// A random permutation of 0..n-1 into `order` (resized; no allocation once it is large enough): pairs the
// strata of two jittered grids without lining them up.
void shuffledStrata(int n, PairRandom& random, std::vector<int>& order);

// Stratified samples for the further dimensions of a batch of n paths (pbrt's "padding"): dimension d of
// path k is drawn from stratum order_d[k] of its own jittered grid of n, each order a random permutation.
// Every dimension is then stratified over the batch, and no two line up; a dimension past the last padded one
// is plain uniform (unbiased either way).
class PaddedStrata {
 public:
  PaddedStrata(int n, int dimensions, PairRandom& random);
  Vec2 sample(int dimension, int k, PairRandom& random) const;

 private:
  StrataGrid grid_;
  std::vector<std::vector<int>> orders_;
};

// Maps (u, v) in [0,1]^2 to a uniformly distributed point on a convex polygon (fan triangles chosen by area
// with u, then the square-to-triangle map), preserving stratification.
Vec3 pointOnPolygon(const Vec3* polygon, int count, double u, double v);

// pointOnPolygon with the fan's triangle areas computed once (the polygon must outlive the sampler).
class PolygonSampler {
 public:
  PolygonSampler(const Vec3* polygon, int count);
  Vec3 point(double u, double v) const;

 private:
  const Vec3* polygon_;
  int triangles_;
  double areas_[16];
  double total_ = 0;
};
inline Vec3 pointOnPolygon(const Polygon& polygon, double u, double v) {
  return pointOnPolygon(polygon.data(), static_cast<int>(polygon.size()), u, v);
}

// Cosine-distributed direction about `normal` from (u, v) in [0,1]^2 (Malley's method: uniform disk, lifted).
Vec3 cosineDirection(const Vec3& normal, double u, double v);

}  // namespace rt
