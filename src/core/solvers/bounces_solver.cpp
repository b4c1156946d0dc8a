#include "core/solvers/bounces_solver.h"

#include "core/solvers/gather_products.h"

namespace rt {

SolverStatus neumannSeries(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                           const IterationSink& sink, std::vector<RgbField>* terms) {
  using namespace solver_detail;
  B = system.emission;
  if (terms) terms->clear();
  const SolverStatus valid = validate(system, true);
  if (valid != SolverStatus::Success) return valid;
  if (terms) terms->push_back(system.emission);
  const GatherRecorder record(system);
  const Stopwatch clock;
  RgbField term = system.emission;
  for (int k = 1, cap = sweepCap(options); k <= cap; ++k) {
    term = (system.reflectance.array() * productWithF(*system.F, term).array()).matrix();  // one more bounce
    if (!term.allFinite()) return SolverStatus::NumericalIssue;
    B += term;
    if (terms) terms->push_back(term);
    IterationRecord r = record(B, productWithF(*system.F, B), k, clock.seconds());
    const double residual = r.residual;
    if (sink) sink(std::move(r));
    if (residual <= options.tolerance) return SolverStatus::Success;
  }
  return SolverStatus::NoConvergence;
}

BouncesSolver::BouncesSolver() : AlgorithmSolver("bounces", nullptr) {}

RgbField BouncesSolver::solve() {
  terms_.clear();
  return run([this](RgbField& B) {
    return neumannSeries(
        *system_, B, options_, [this](IterationRecord r) { onRecord(std::move(r)); }, &terms_);
  });
}

}  // namespace rt
