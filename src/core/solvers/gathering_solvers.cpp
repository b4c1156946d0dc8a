#include "core/solvers/gathering_solvers.h"

#include "core/solvers/gather_products.h"
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

// What both splittings start from: B = E, the system checked, and the divisor (none may be 0).
SolverStatus start(const RadiositySystem& system, RgbField& B, RgbField& divisor) {
  B = system.emission;
  const SolverStatus valid = validate(system, true);
  if (valid != SolverStatus::Success) return valid;
  divisor = selfDivisor(system);
  if ((divisor.array() <= 0.0).any()) return SolverStatus::NumericalIssue;  // rho = 1 and F_ii = 1
  return SolverStatus::Success;
}

// Jacobi's loop: `sweep(B, divisor, FB)` updates B in place from FB = F B of before the sweep; afterwards
// the exact residual decides, and its product F B is the next sweep's FB: one pass over F per sweep.
template <typename Sweep>
SolverStatus iterate(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                     const IterationSink& sink, Sweep&& sweep) {
  RgbField divisor;
  const SolverStatus started = start(system, B, divisor);
  if (started != SolverStatus::Success) return started;
  const GatherRecorder record(system);
  const Stopwatch clock;
  RgbField previous, FB = productWithF(*system.F, B);
  for (int k = 1, cap = sweepCap(options); k <= cap; ++k) {
    previous = B;
    sweep(B, divisor, FB);
    if (!B.allFinite()) {
      B = previous;  // never hand out NaN: keep the last finite iterate
      return SolverStatus::NumericalIssue;
    }
    FB = productWithF(*system.F, B);
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
  return iterate(system, B, options, sink,
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

// The residual of sweep k's B needs F B_k, and sweep k + 1 reads every row of F with B_k beside it: one
// reading of each row gives both (SweepState), so a sweep and the residual of the iterate it starts from take
// one pass over F, not two. The record of B_k then waits for sweep k + 1, which is wasted if B_k converged;
// when the residuals' rate of decrease predicts that B_k is the last iterate, its residual takes a product
// alone instead. Either way the iterates, the records and the answer are those of a sweep then a residual.
SolverStatus gaussSeidel(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                         const IterationSink& sink) {
  const double omega = options.relaxation;
  B = system.emission;
  if (!(omega > 0.0 && omega < 2.0)) return SolverStatus::InvalidInput;  // SOR diverges outside (0, 2)
  RgbField divisor;
  const SolverStatus started = start(system, B, divisor);
  if (started != SolverStatus::Success) return started;
  const GatherRecorder record(system);
  const Stopwatch clock;
  const FormFactorMatrix& F = *system.F;
  SweepState state(B);
  RgbField FB(F.rows(), 3);
  // One sweep; with `product`, FB = F times the B it starts from.
  auto sweep = [&](bool product) {
    state.startSweep();
    Eigen::RowVector3d last;
    for (Eigen::Index i = 0; i < F.rows(); ++i) {
      const bool black = isBlack(system, i);
      if (black && !product) continue;
      // Row i of F times the current B: rows before i already hold this sweep's values.
      const Eigen::RowVector3d gathered = state.gather(F, i, product ? &last : nullptr);
      if (product) FB.row(i) = last;
      if (black) continue;
      const Eigen::RowVector3d current = state.row(i);
      const Eigen::RowVector3d others = gathered - F(i, i) * current;
      const Eigen::RowVector3d updated =
          ((system.emission.row(i).array() + system.reflectance.row(i).array() * others.array()) /
           divisor.row(i).array())
              .matrix();
      state.setRow(i, (1.0 - omega) * current + omega * updated);
    }
  };
  const int cap = sweepCap(options);
  RgbField previous = B;
  sweep(false);
  RgbField current = state.current();
  double residual1 = 0, residual2 = 0;  // of the last two iterates
  for (int k = 1;; ++k) {
    if (!current.allFinite()) {
      B = previous;  // never hand out NaN: keep the last finite iterate
      return SolverStatus::NumericalIssue;
    }
    const bool likelyLast =
        k >= cap || (residual2 > 0 && residual1 * (residual1 / residual2) <= options.tolerance);
    if (likelyLast)
      FB = productWithF(F, current);
    else
      sweep(true);  // the state now holds iterate k + 1
    IterationRecord r = record(current, FB, k, clock.seconds());
    const double residual = r.residual;
    if (sink) sink(std::move(r));
    if (residual <= options.tolerance || k >= cap) {
      B = std::move(current);
      return residual <= options.tolerance ? SolverStatus::Success : SolverStatus::NoConvergence;
    }
    if (likelyLast) sweep(false);
    residual2 = residual1;
    residual1 = residual;
    previous = std::move(current);
    current = state.current();
  }
}

}  // namespace rt
