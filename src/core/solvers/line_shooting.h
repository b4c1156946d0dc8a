// One round of local lines traced through the geometry, shared by the two stochastic Jacobi solvers that
// store no form factor (local_lines_solver.h): `rays` lines leave the elements, each element chosen with
// probability proportional to the power it shoots (summed over the channels), the origin uniform on it and
// the direction cosine-distributed about its normal. The first element a line hits, on its front side,
// receives the line's share of the power; a line that escapes or hits the back of a polygon is lost. Because
// a cosine-distributed line from a uniform point of i lands first on j with probability F_ij (Dutré, Bekaert
// and Bala 2006, sec. 6.2.2), the expected power received by j is sum_i P_i F_ij: one Jacobi product F^T P,
// estimated without computing a form factor.
//
// Two options lower the noise of a round (Dutré, Bekaert and Bala 2006, sec. 6.6): quasi-Monte
// Carlo lines (LineSampling::Sobol: the source, origin and direction of ray r come from point r of a
// scrambled 4-dimensional Sobol set, line_sampling.h) and a constant control variate (LineShot::
// control = beta): the lines shoot B_i - beta instead of B_i, signed, so that their total power
// sum_i |B_i - beta| A_i, on which the noise depends, is smaller; the caller adds back the known part,
// beta A_j R_j with R_j = sum_i F_ji the row sum of j (rowSums; 1 in a closed scene).
//
// Deterministic for (seed, round) at any thread count: rays are cut into fixed chunks, each with its own
// random stream seeded from (seed, round, chunk), and the scores are added in 2^-32 fixed point, whose
// integer sums do not depend on the order the threads add them in.
#pragma once

#include <cstdint>
#include <memory>

#include "core/formfactor/line_sampling.h"
#include "core/mesh.h"
#include "core/vec.h"

namespace rt {

struct LineRound {
  RgbField received;     // n x 3: power landing on each element's front side (W per channel)
  RgbField sumVariance;  // n x 3: the variance of `received`, estimated from the same scores
  double shot = 0;       // the power shot (all channels)
  double lost = 0;       // the power of the lines that escaped or hit a back side (all channels, signed)
  long rays = 0;
};

struct LineShot {
  LineSampling sampling = LineSampling::Random;
  Eigen::RowVector3d control = Eigen::RowVector3d::Zero();  // beta per channel, subtracted before shooting
};

// The constant control variate that makes the shot power sum_i A_i |B_i - beta| smallest, per channel: the
// area-weighted median of the radiosities (half the area on either side). The noise of a round grows with
// that power (local_lines_solver.h), so this beta is the best constant for it.
Eigen::RowVector3d constantControl(const RgbField& radiosity, const Eigen::VectorXd& areas);

// The lines per element of the row sums the control variate needs (LineShooter::rowSums).
constexpr int kRowSumLines = 256;

class LineShooter {
 public:
  // The mesh must outlive the shooter.
  explicit LineShooter(const Mesh& mesh);
  ~LineShooter();
  LineShooter(const LineShooter&) = delete;
  LineShooter& operator=(const LineShooter&) = delete;

  // Shoots the power (radiosity_i - control) A_i of every element with `rays` lines, each element chosen
  // with probability proportional to sum_c |radiosity_ic - control_c| A_i, so that every line carries the
  // same absolute power `shot / rays`, signed per channel. Returns a round with nothing received when no
  // element has power to shoot.
  LineRound shoot(const RgbField& radiosity, long rays, std::uint64_t seed, int round,
                  const LineShot& how = {});
  // R_j, the fraction of cosine-distributed lines from a uniform point of each element that land on the
  // front of an element: the row sum sum_k F_jk, estimated with `perElement` scrambled Sobol lines per
  // element (exact, 1, wherever every line hits a front, as in a closed scene).
  Eigen::VectorXd rowSums(int perElement, std::uint64_t seed);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rt
