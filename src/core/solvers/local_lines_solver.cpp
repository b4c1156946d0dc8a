#include "core/solvers/local_lines_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/solvers/line_shooting.h"
#include "core/solvers/solver_support.h"

namespace rt {

namespace {

using namespace solver_detail;

// The checks both solvers make; InvalidInput without a mesh of the system's size.
SolverStatus validateGeometry(const RadiositySystem& system) {
  const SolverStatus valid = validate(system, false);
  if (valid != SolverStatus::Success) return valid;
  if (!system.mesh || system.mesh->size() != system.size()) return SolverStatus::InvalidInput;
  return SolverStatus::Success;
}

long budgetOf(const RadiositySystem& system, const SolverOptions& options) {
  return options.raysPerIteration > 0 ? options.raysPerIteration : localLinesDefaultRays(system.size());
}

// One round of lines, with the options' sampling and control variate. The control's known part, beta A_j R_j,
// is added to what each element receives, and what escapes of it to the lost power; the row sums are
// estimated the first time a nonzero beta needs them (their rays are added to `rays`).
class Rounds {
 public:
  Rounds(const RadiositySystem& system, const SolverOptions& options)
      : system_(system), options_(options), shooter_(*system.mesh) {}

  LineRound shoot(const RgbField& radiosity, long count, int round, long& rays) {
    LineShot how{options_.sampling, Eigen::RowVector3d::Zero()};
    if (options_.controlVariate) how.control = constantControl(radiosity, system_.areas);
    LineRound out = shooter_.shoot(radiosity, count, options_.seed, round, how);
    rays += count;
    if (how.control.isZero()) return out;
    if (rowSums_.size() == 0) {
      rowSums_ = shooter_.rowSums(kRowSumLines, options_.seed);
      rays += kRowSumLines * static_cast<long>(system_.size());
    }
    const Eigen::VectorXd& A = system_.areas;
    out.received += (A.cwiseProduct(rowSums_) * how.control).eval();
    out.lost += how.control.sum() * (A.sum() - A.dot(rowSums_));
    return out;
  }

 private:
  const RadiositySystem& system_;
  const SolverOptions& options_;
  LineShooter shooter_;
  Eigen::VectorXd rowSums_;
};

}  // namespace

long localLinesDefaultRays(std::size_t elements) {
  return std::max<long>(100000, 1000 * static_cast<long>(elements));
}

int regularBurnIn(double rhoMax, double tolerance) {
  if (rhoMax <= 0.0 || tolerance >= 1.0) return 0;
  if (rhoMax >= 1.0 || tolerance <= 0.0) return std::numeric_limits<int>::max();
  return static_cast<int>(std::ceil(std::log(tolerance) / std::log(rhoMax)));
}

SolverStatus localLines(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                        const IterationSink& sink, RgbField* standardError) {
  B = system.emission;
  const auto n = static_cast<Eigen::Index>(system.size());
  RgbField variance = RgbField::Zero(n, 3);
  if (standardError) *standardError = variance;
  const SolverStatus valid = validateGeometry(system);
  if (valid != SolverStatus::Success) return valid;
  const Eigen::VectorXd& A = system.areas;
  const Stopwatch clock;
  const long budget = budgetOf(system, options);

  RgbField unshot = system.emission;
  const double emitted = totalEmittedPower(system);
  if (emitted <= 0.0) return SolverStatus::Success;
  Rounds rounds(system, options);
  const double eNorm = system.emission.norm();
  double absorbed = 0.0, escaped = 0.0;
  long raysSoFar = 0;

  for (int k = 1, cap = sweepCap(options); k <= cap; ++k) {
    const double total = unshot.rowwise().sum().cwiseProduct(A).sum();
    if (total <= 0.0) return SolverStatus::Success;
    // Constant power per ray; the shrink by 1e-12 keeps the count independent of the units (see
    // stochasticJacobi).
    const long rays =
        std::max(1L, static_cast<long>(std::ceil(double(budget) * (total / emitted) * (1.0 - 1e-12))));
    const LineRound round = rounds.shoot(unshot, rays, k, raysSoFar);
    escaped += round.lost;
    for (Eigen::Index j = 0; j < n; ++j) {
      const Eigen::Array3d rho = system.reflectance.row(j).array().transpose();
      const Eigen::Array3d in = round.received.row(j).array().transpose();
      absorbed += ((1.0 - rho) * in).sum();
      const Eigen::Array3d gain = rho * in / A(j);
      unshot.row(j) = gain.matrix().transpose();
      B.row(j) += gain.matrix().transpose();
      variance.row(j) +=
          (rho.square() * round.sumVariance.row(j).array().transpose() / (A(j) * A(j))).matrix().transpose();
    }
    IterationRecord rec;
    rec.iteration = k;
    rec.B = B;
    rec.unshot = unshot;
    rec.unshotPower = unshot.rowwise().sum().cwiseProduct(A).sum();
    rec.emittedPower = emitted;
    rec.absorbedPower = absorbed;
    rec.escapedPower = escaped;
    rec.residual = eNorm > 0 ? unshot.norm() / eNorm : unshot.norm();
    rec.standardError = relativeAreaRms(variance.cwiseSqrt(), B, A);
    rec.rays = raysSoFar;
    rec.seconds = clock.seconds();
    const bool done = rec.unshotPower <= options.tolerance * emitted;
    if (!B.allFinite()) return SolverStatus::NumericalIssue;
    if (standardError) *standardError = variance.cwiseSqrt();
    if (sink) sink(std::move(rec));
    if (done) return SolverStatus::Success;
  }
  return SolverStatus::NoConvergence;
}

SolverStatus regularLocalLines(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                               const IterationSink& sink, RgbField* standardError) {
  B = system.emission;
  const auto n = static_cast<Eigen::Index>(system.size());
  if (standardError) *standardError = RgbField::Zero(n, 3);
  const SolverStatus valid = validateGeometry(system);
  if (valid != SolverStatus::Success) return valid;
  const Eigen::VectorXd& A = system.areas;
  const Stopwatch clock;
  const long rays = budgetOf(system, options);
  const double emitted = totalEmittedPower(system);
  if (emitted <= 0.0) return SolverStatus::Success;
  const double rhoMax = system.reflectance.maxCoeff();
  const int burnIn = regularBurnIn(rhoMax, options.tolerance);
  Rounds rounds(system, options);

  // The iterate B^(k) and, from k > burnIn, the sum of the iterates and of the variances each one's own
  // lines added (the noise an iterate inherits from the ones before is not counted, as in localLines).
  RgbField current = system.emission;
  RgbField sum = RgbField::Zero(n, 3), varianceSum = RgbField::Zero(n, 3);
  int kept = 0;
  long raysSoFar = 0;
  for (int k = 1, cap = sweepCap(options); k <= cap; ++k) {
    const LineRound round = rounds.shoot(current, rays, k, raysSoFar);
    RgbField next = system.emission, fresh(n, 3);
    double absorbed = 0.0;
    for (Eigen::Index j = 0; j < n; ++j) {
      const Eigen::Array3d rho = system.reflectance.row(j).array().transpose();
      const Eigen::Array3d in = round.received.row(j).array().transpose();
      absorbed += ((1.0 - rho) * in).sum();
      next.row(j) += (rho * in / A(j)).matrix().transpose();
      fresh.row(j) =
          (rho.square() * round.sumVariance.row(j).array().transpose() / (A(j) * A(j))).matrix().transpose();
    }
    current = next;
    if (!current.allFinite()) return SolverStatus::NumericalIssue;
    IterationRecord rec;
    rec.iteration = k;
    rec.emittedPower = emitted;
    rec.absorbedPower = absorbed;
    rec.escapedPower = round.lost;
    rec.rays = raysSoFar;
    RgbField se;
    if (k > burnIn) {
      sum += current;
      varianceSum += fresh;
      ++kept;
      B = sum / double(kept);
      se = varianceSum.cwiseSqrt() / double(kept);
      rec.standardError = relativeAreaRms(se, B, A);
      rec.residual = rec.standardError;
    } else {
      B = current;
      se = fresh.cwiseSqrt();
      rec.standardError = relativeAreaRms(se, B, A);
      // What is left of the start B^(0) = E in this iterate, at most rhoMax^k of B (rows of F sum to <= 1).
      rec.residual = std::pow(rhoMax, k);
    }
    rec.B = B;
    rec.seconds = clock.seconds();
    const bool done = k > burnIn && rec.standardError <= options.tolerance;
    if (standardError) *standardError = se;
    if (sink) sink(std::move(rec));
    if (done) return SolverStatus::Success;
  }
  return SolverStatus::NoConvergence;
}

}  // namespace rt
