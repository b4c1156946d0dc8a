// One round of local lines traced through the geometry, shared by the two stochastic Jacobi solvers that
// store no form factor (local_lines_solver.h): `rays` lines leave the elements, each element chosen with
// probability proportional to the power it shoots (summed over the channels), the origin uniform on it and
// the direction cosine-distributed about its normal. The first element a line hits, on its front side,
// receives the line's share of the power; a line that escapes or hits the back of a polygon is lost. Because
// a cosine-distributed line from a uniform point of i lands first on j with probability F_ij (Dutré, Bekaert
// and Bala 2006, sec. 6.2.2), the expected power received by j is sum_i P_i F_ij: one Jacobi product F^T P,
// estimated without computing a form factor.
//
// Deterministic for (seed, round) at any thread count: rays are cut into fixed chunks, each with its own
// random stream seeded from (seed, round, chunk), and the scores are added in 2^-32 fixed point, whose
// integer sums do not depend on the order the threads add them in.
#pragma once

#include <cstdint>
#include <memory>

#include "core/mesh.h"
#include "core/vec.h"

namespace rt {

struct LineRound {
  RgbField received;     // n x 3: power landing on each element's front side (W per channel)
  RgbField sumVariance;  // n x 3: the variance of `received`, estimated from the same scores
  double shot = 0;       // the power shot (all channels)
  double lost = 0;       // the power of the lines that escaped or hit a back side (all channels)
  long rays = 0;
};

class LineShooter {
 public:
  // The mesh must outlive the shooter.
  explicit LineShooter(const Mesh& mesh);
  ~LineShooter();
  LineShooter(const LineShooter&) = delete;
  LineShooter& operator=(const LineShooter&) = delete;

  // Shoots the power radiosity_i A_i of every element with `rays` lines (each carrying shot / rays).
  // Returns a round with nothing received when no element has power to shoot.
  LineRound shoot(const RgbField& radiosity, long rays, std::uint64_t seed, int round);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rt
