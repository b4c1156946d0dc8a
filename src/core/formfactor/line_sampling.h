// How the stochastic line methods draw the numbers of a line (its source, origin and direction): plain
// pseudo-random numbers, or a quasi-Monte Carlo point set, the Sobol sequence (Sobol 1967; Keller 1996 used
// such low-discrepancy sequences for radiosity lines). A Sobol set of N points fills the unit cube far more
// evenly than N random points, so an average over it has an error that falls faster than 1/sqrt(N) for
// integrands of bounded variation (Niederreiter 1992, the Koksma-Hlawka inequality). A line's landing
// element is discontinuous along visibility and element boundaries, so the gain is less than for smooth
// integrands; docs/benchmarks.md measures it.
//
// The points come from Boost.Random's Sobol generator (Joe and Kuo's direction numbers), scrambled by a
// random digital shift: every coordinate of every point is XOR-ed with one 32-bit number per dimension drawn
// from (seed, stream). The shift keeps the set's even spread (a digital net stays a net) and makes each point
// uniform on the cube, so an average over the points is an unbiased estimate whatever the seed, and the
// spread of the estimates over seeds measures the error (Owen 1995 gives the general scrambling; the shift
// is its simplest case). Unscrambled, one fixed point set would be one fixed error, the same for every seed.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rt {

enum class LineSampling { Random, Sobol };

// "random", "sobol": the values of the `sampling` step key and CLI option, in this order.
const std::vector<std::string>& lineSamplingNames();
std::string toString(LineSampling sampling);
std::optional<LineSampling> parseLineSampling(const std::string& name);

// The points of a d-dimensional scrambled Sobol sequence, from a given index on. Point k is the same for
// every object of the same (dimensions, seed, stream), so threads can each take a contiguous run of indices.
class ScrambledSobol {
 public:
  static constexpr int kMaxDimensions = 16;
  // dimensions is clamped to [1, kMaxDimensions].
  ScrambledSobol(int dimensions, std::uint64_t seed, std::uint64_t stream);
  ~ScrambledSobol();
  ScrambledSobol(const ScrambledSobol&) = delete;
  ScrambledSobol& operator=(const ScrambledSobol&) = delete;

  int dimensions() const { return dimensions_; }
  // The next point is point `index` (index < 2^32, the length of the 32-bit sequence).
  void start(std::uint64_t index);
  // Writes the next point's `dimensions()` coordinates, each in [0, 1), and moves on by one point.
  void next(double* point);

 private:
  struct Engine;
  std::unique_ptr<Engine> engine_;
  int dimensions_;
  std::uint64_t index_ = 0;
  std::uint32_t shift_[kMaxDimensions];
};

}  // namespace rt
