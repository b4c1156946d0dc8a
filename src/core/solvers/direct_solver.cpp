#include "core/solvers/direct_solver.h"

#include <Eigen/LU>

#include "core/assembly.h"
#include "core/solvers/gather_products.h"
#include "core/solvers/solver_support.h"

namespace rt {

SolverStatus directSolve(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                         const IterationSink& sink) {
  using namespace solver_detail;
  B = system.emission;
  const SolverStatus valid = validate(system, true);
  if (valid != SolverStatus::Success) return valid;
  const Stopwatch clock;
  RgbField solution(system.size(), 3);
  for (int c = 0; c < 3; ++c) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(assembleDense(*system.F, system.reflectance.col(c)));
    solution.col(c) = lu.solve(system.emission.col(c));
  }
  if (!solution.allFinite()) return SolverStatus::NumericalIssue;
  B = solution;
  IterationRecord r = GatherRecorder(system)(B, productWithF(*system.F, B), 1, clock.seconds());
  // A residual far above rounding means K was (numerically) singular: the numbers are not a solution.
  const bool accurate = r.residual <= std::max(1e-8, 100 * options.tolerance);
  if (sink) sink(std::move(r));
  return accurate ? SolverStatus::Success : SolverStatus::NumericalIssue;
}

}  // namespace rt
