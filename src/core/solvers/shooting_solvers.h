// Shooting: instead of every element gathering, the element with the most unshot power (B_unshot,i * A_i,
// summed over channels) sends it to everything it sees, and each receiver reflects rho_j of it (Southwell
// relaxation; Cohen, Chen, Wallace, Greenberg 1988 "progressive refinement"). One iteration = one shot, O(n).
// Because the brightest sources go first, a useful picture appears after a few shots.
//
// With the matrix, the shot from i uses column i of F (F_ji A_j / A_i of i's power arrives at j), which is
// exact for the system as given. With a row provider, only row i is needed (F_ij of i's power arrives at j)
// and no n x n matrix is ever stored: a hemicube or ray caster placed at the shooter computes it on the fly;
// the two agree when F is reciprocal. Stops when the unshot power is <= options.tolerance times the emitted
// power.
//
// Energy bookkeeping is exact at every shot: emitted = absorbed + escaped + unshot power.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <span>

#include "core/solvers/solver.h"
#include "core/solvers/solver_support.h"

namespace rt {

// Writes F_i0 .. F_i,n-1 into `row` (n entries, every one written): what element i sees. The caller owns the
// storage, so a row goes straight where it is kept (a matrix row, a block sent to another worker).
using FormFactorRowProvider = std::function<void(int i, std::span<double> row)>;

// Southwell shooting with the stored matrix (system.F).
SolverStatus southwell(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                       const IterationSink& sink = {});
// Southwell shooting without a stored matrix: system.F may be null (the recorded residual is then ||unshot||
// / ||E||, the residual of B - unshot, instead of the exact ||K B - E|| / ||E||).
SolverStatus southwell(const RadiositySystem& system, const FormFactorRowProvider& rows, RgbField& B,
                       const SolverOptions& options, const IterationSink& sink = {});
// Progressive refinement: Southwell plus, when options.ambient, the ambient term in the displayed B
// (B + rho * ambient). `rows` may be empty to use system.F.
SolverStatus progressiveRefinement(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                                   const IterationSink& sink = {}, const FormFactorRowProvider& rows = {});

// Cohen et al.'s ambient term for the unshot radiosity: R * sum_j unshot_j A_j / sum_j A_j per channel, with
// the overall interreflection factor R = 1 / (1 - rho_avg) and rho_avg the area-weighted mean reflectance.
Rgb ambientTerm(const RadiositySystem& system, const RgbField& unshot);

// "southwell" and "progressive" in the registry. setRowProvider() switches to the matrix-free mode.
class ShootingSolver : public solver_detail::AlgorithmSolver {
 public:
  explicit ShootingSolver(bool progressive);
  void setRowProvider(FormFactorRowProvider rows) { rows_ = std::move(rows); }
  RgbField solve() override;

 private:
  bool progressive_;
  FormFactorRowProvider rows_;
};

}  // namespace rt
