#include "core/solvers/solver.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace rt {

std::string toString(SolverStatus status) {
  switch (status) {
    case SolverStatus::Success:
      return "success";
    case SolverStatus::NoConvergence:
      return "no convergence";
    case SolverStatus::NumericalIssue:
      return "numerical issue";
    case SolverStatus::InvalidInput:
      return "invalid input";
    case SolverStatus::Cancelled:
      return "cancelled";
  }
  return "unknown";
}

int sweepCap(const SolverOptions& options) {
  return options.maxIterations > 0 ? options.maxIterations : 1000;
}

int shotCap(const SolverOptions& options, long long elements) {
  if (options.maxIterations > 0) return options.maxIterations;
  return static_cast<int>(std::clamp<long long>(100 * elements, 1000, 100'000'000));
}

void Solver::record(IterationRecord r) {
  if (observer_) observer_(r);
  if (options_.recordHistory) history_.push_back(std::move(r));
  if (progress_ && progress_->cancelled()) throw Cancelled();
}

}  // namespace rt
