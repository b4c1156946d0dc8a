#include "core/solvers/solver_support.h"

#include <algorithm>
#include <cmath>

#include "core/solvers/energy.h"
#include "core/solvers/gather_products.h"

namespace rt::solver_detail {

SolverStatus validate(const RadiositySystem& system, bool needMatrix) {
  const Eigen::Index n = system.areas.size();
  if (system.reflectance.rows() != n || system.emission.rows() != n) return SolverStatus::InvalidInput;
  if (needMatrix && (!system.F || system.F->rows() != n || system.F->cols() != n))
    return SolverStatus::InvalidInput;
  if (!system.areas.allFinite() || (system.areas.array() <= 0.0).any()) return SolverStatus::InvalidInput;
  if (!system.reflectance.allFinite() || (system.reflectance.array() < 0.0).any() ||
      (system.reflectance.array() > 1.0).any())
    return SolverStatus::InvalidInput;
  if (!system.emission.allFinite() || (system.emission.array() < 0.0).any())
    return SolverStatus::InvalidInput;
  if (system.F) {
    // Row by row: Eigen's allFinite() of the whole matrix forms F - F, a second matrix of F's size. A
    // finite sum has only finite entries; only a row whose sum is not finite is looked at entry by entry
    // (finite entries may overflow).
    for (Eigen::Index i = 0; i < n; ++i)
      if (!std::isfinite(sumOf(system.F->row(i).data(), n)) && !system.F->row(i).allFinite())
        return SolverStatus::InvalidInput;
  }
  return SolverStatus::Success;
}

double totalEmittedPower(const RadiositySystem& system) {
  return emittedPower(system).sum();
}

GatherRecorder::GatherRecorder(const RadiositySystem& system)
    : system_(system), emitted_(totalEmittedPower(system)) {
  const FormFactorMatrix& F = *system.F;
  Eigen::VectorXd rowSums;
  absorbing_ =
      system.areas.asDiagonal() * productWithF(F, (1.0 - system.reflectance.array()).matrix(), &rowSums);
  escaping_ = (system.areas.array() * (1.0 - rowSums.array())).matrix();
}

IterationRecord GatherRecorder::operator()(const RgbField& B, const RgbField& FB, int iteration,
                                           double seconds) const {
  IterationRecord r;
  r.iteration = iteration;
  r.B = B;
  r.residual = system_.relativeResidual(B, FB);
  r.emittedPower = emitted_;
  r.absorbedPower = (B.array() * absorbing_.array()).sum();
  r.escapedPower = (B.transpose() * escaping_).sum();
  r.seconds = seconds;
  return r;
}

double relativeAreaRms(const RgbField& error, const RgbField& B, const Eigen::VectorXd& areas) {
  const double e = error.rowwise().squaredNorm().dot(areas), b = B.rowwise().squaredNorm().dot(areas);
  return b > 0 ? std::sqrt(e / b) : std::sqrt(e / areas.sum());
}

std::size_t sampleCumulative(const std::vector<double>& cumulative, double target) {
  return static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), target) -
                                  cumulative.begin());
}

void AlgorithmSolver::onRecord(IterationRecord r) {
  iterations_ = r.iteration;
  error_ = r.residual;
  if (progress_) {
    const double byCount = options_.maxIterations > 0 ? double(r.iteration) / options_.maxIterations : 0.0;
    const double byError = (r.residual > 0 && options_.tolerance > 0 && options_.tolerance < 1)
                               ? std::log(r.residual) / std::log(options_.tolerance)
                               : 0.0;
    progressShown_ = std::max(progressShown_, std::clamp(std::max(byCount, byError), 0.0, 1.0));
    progress_->report(progressShown_, "solve (" + name_ + ")");
  }
  record(std::move(r));
}

RgbField AlgorithmSolver::solve() {
  return run([this](RgbField& B) {
    return algorithm_(*system_, B, options_, [this](IterationRecord r) { onRecord(std::move(r)); });
  });
}

}  // namespace rt::solver_detail
