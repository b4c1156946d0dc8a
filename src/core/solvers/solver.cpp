#include "core/solvers/solver.h"

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

void Solver::record(IterationRecord r) {
  if (observer_) observer_(r);
  if (options_.recordHistory) history_.push_back(std::move(r));
  if (progress_ && progress_->cancelled()) throw Cancelled();
}

}  // namespace rt
