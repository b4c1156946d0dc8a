#include "core/solvers/gathering_solvers.h"

#include "core/solvers/solver_support.h"

namespace rt {

namespace {

using namespace solver_detail;

// 1 - rho_i F_ii per channel; the divisor of both splittings.
RgbField selfDivisor(const RadiositySystem& system) {
  RgbField d(system.size(), 3);
  for (Eigen::Index i = 0; i < d.rows(); ++i)
    d.row(i) = 1.0 - system.reflectance.row(i).array() * (*system.F)(i, i);
  return d;
}

// Shared loop: `sweep(B, divisor, FB)` updates B in place, FB = F B from before the sweep when
// kReusesProduct (else empty); afterwards the exact residual decides. The residual's product F B is the next
// sweep's FB: one pass over F per sweep where the sweep needs no other.
template <bool kReusesProduct, typename Sweep>
SolverStatus iterate(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                     const IterationSink& sink, Sweep&& sweep) {
  B = system.emission;
  const SolverStatus valid = validate(system, true);
  if (valid != SolverStatus::Success) return valid;
  const RgbField divisor = selfDivisor(system);
  if ((divisor.array() <= 0.0).any()) return SolverStatus::NumericalIssue;  // rho = 1 and F_ii = 1
  const GatherRecorder record(system);
  const Stopwatch clock;
  RgbField previous, FB;
  if (kReusesProduct) FB = (*system.F) * B;
  for (int k = 1, cap = sweepCap(options); k <= cap; ++k) {
    previous = B;
    sweep(B, divisor, FB);
    if (!B.allFinite()) {
      B = previous;  // never hand out NaN: keep the last finite iterate
      return SolverStatus::NumericalIssue;
    }
    FB = (*system.F) * B;
    IterationRecord r = record(B, FB, k, clock.seconds());
    const double residual = r.residual;
    if (sink) sink(std::move(r));
    if (residual <= options.tolerance) return SolverStatus::Success;
  }
  return SolverStatus::NoConvergence;
}

}  // namespace

SolverStatus jacobi(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                    const IterationSink& sink) {
  return iterate<true>(system, B, options, sink,
                       [&system](RgbField& current, const RgbField& divisor, const RgbField& gathered) {
                         // gathered = F B: all rows from the previous sweep's values
                         const FormFactorMatrix& F = *system.F;
                         for (Eigen::Index i = 0; i < current.rows(); ++i) {
                           if (isBlack(system, i)) continue;
                           const Eigen::RowVector3d others = gathered.row(i) - F(i, i) * current.row(i);
                           current.row(i) = (system.emission.row(i).array() +
                                             system.reflectance.row(i).array() * others.array()) /
                                            divisor.row(i).array();
                         }
                       });
}

SolverStatus gaussSeidel(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                         const IterationSink& sink) {
  const double omega = options.relaxation;
  if (!(omega > 0.0 && omega < 2.0)) {
    B = system.emission;
    return SolverStatus::InvalidInput;  // SOR diverges outside (0, 2)
  }
  return iterate<false>(
      system, B, options, sink,
      [&system, omega](RgbField& current, const RgbField& divisor, const RgbField&) {
        const FormFactorMatrix& F = *system.F;
        for (Eigen::Index i = 0; i < current.rows(); ++i) {
          if (isBlack(system, i)) continue;
          // Row i of F times the current B: rows before i already hold this sweep's values.
          const Eigen::RowVector3d others = F.row(i) * current - F(i, i) * current.row(i);
          const Eigen::RowVector3d updated =
              ((system.emission.row(i).array() + system.reflectance.row(i).array() * others.array()) /
               divisor.row(i).array())
                  .matrix();
          current.row(i) = (1.0 - omega) * current.row(i) + omega * updated;
        }
      });
}

}  // namespace rt
