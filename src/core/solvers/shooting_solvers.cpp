#include "core/solvers/shooting_solvers.h"

#include <algorithm>

namespace rt {

namespace {

using namespace solver_detail;

SolverStatus shoot(const RadiositySystem& system, const FormFactorRowProvider* rows, bool withAmbient,
                   RgbField& B, const SolverOptions& options, const IterationSink& sink) {
  B = system.emission;
  const SolverStatus valid = validate(system, rows == nullptr);
  if (valid != SolverStatus::Success) return valid;
  const auto n = static_cast<Eigen::Index>(system.size());
  const Eigen::VectorXd& A = system.areas;
  const RgbField& rho = system.reflectance;
  const bool haveMatrix = system.F && system.F->rows() == n;
  const Stopwatch clock;

  RgbField unshot = system.emission;
  Eigen::VectorXd power = unshot.rowwise().sum().cwiseProduct(A);  // per element, all channels
  const double emitted = power.sum();
  if (emitted <= 0.0) return SolverStatus::Success;  // nothing to shoot: B = E = 0 is the solution
  double absorbed = 0.0, escaped = 0.0;
  // The exact residual costs O(n^2), a shot O(n): for large n it is refreshed every few shots only.
  const int residualEvery = options.residualEvery > 0 ? options.residualEvery
                                                      : static_cast<int>(std::max<Eigen::Index>(1, n / 512));
  double residual = 1.0;
  const double eNorm = system.emission.norm();
  Eigen::VectorXd fraction(n), row(n);

  const int cap = shotCap(options, n);
  for (int k = 1; k <= cap; ++k) {
    Eigen::Index shooter = 0;
    const double shotPower = power.maxCoeff(&shooter);
    if (shotPower <= 0.0) return SolverStatus::Success;  // everything shot (possible when all rho are 0)
    // Share of the shooter's power that arrives at each element.
    if (rows) {
      (*rows)(static_cast<int>(shooter), {row.data(), static_cast<std::size_t>(n)});
      if (!row.allFinite()) return SolverStatus::InvalidInput;
      fraction = row;
    } else {
      fraction = system.F->col(shooter).cwiseProduct(A) / A(shooter);
    }
    const Eigen::RowVector3d shot = unshot.row(shooter) * A(shooter);  // power per channel
    unshot.row(shooter).setZero();
    power(shooter) = 0.0;
    double arrived = 0.0;
    for (Eigen::Index j = 0; j < n; ++j) {
      const double f = fraction(j);
      if (f == 0.0) continue;
      const Eigen::Array3d incoming = (shot * f).array();
      arrived += incoming.sum();
      const Eigen::Array3d reflected = rho.row(j).array().transpose() * incoming;
      absorbed += incoming.sum() - reflected.sum();
      if ((reflected == 0.0).all()) continue;
      const Eigen::RowVector3d gain = (reflected / A(j)).matrix().transpose();
      B.row(j) += gain;
      unshot.row(j) += gain;
      power(j) = unshot.row(j).sum() * A(j);
    }
    escaped += shot.sum() - arrived;

    IterationRecord r;
    r.iteration = k;
    r.shooter = static_cast<int>(shooter);
    r.unshotPower = power.sum();
    r.emittedPower = emitted;
    r.absorbedPower = absorbed;
    r.escapedPower = escaped;
    const bool done = r.unshotPower <= options.tolerance * emitted;
    const bool last = done || k == cap;
    r.B = B;
    if (withAmbient) {
      const Rgb ambient = ambientTerm(system, unshot);
      r.B += (rho.array().rowwise() * ambient.transpose()).matrix();
    }
    if (!r.B.allFinite()) return SolverStatus::NumericalIssue;
    if (!haveMatrix) {
      residual = eNorm > 0 ? unshot.norm() / eNorm : unshot.norm();
    } else if (k % residualEvery == 0 || last || k == 1) {
      residual = system.relativeResidual(r.B);
    }
    r.residual = residual;
    r.unshot = unshot;
    r.seconds = clock.seconds();
    if (withAmbient && last) B = r.B;  // hand out what was displayed
    if (sink) sink(std::move(r));
    if (done) return SolverStatus::Success;
  }
  return SolverStatus::NoConvergence;
}

}  // namespace

Rgb ambientTerm(const RadiositySystem& system, const RgbField& unshot) {
  const double totalArea = system.areas.sum();
  if (!(totalArea > 0.0)) return Rgb::Zero();
  const Rgb rhoAverage = (system.reflectance.transpose() * system.areas).array() / totalArea;
  const Rgb unshotAverage = (unshot.transpose() * system.areas).array() / totalArea;
  Rgb ambient = Rgb::Zero();
  for (int c = 0; c < 3; ++c) {
    // rho_avg -> 1 would make R infinite; such a scene never converges anyway, so no ambient is shown.
    if (rhoAverage(c) < 1.0 - 1e-12) ambient(c) = unshotAverage(c) / (1.0 - rhoAverage(c));
  }
  return ambient;
}

SolverStatus southwell(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                       const IterationSink& sink) {
  return shoot(system, nullptr, false, B, options, sink);
}

SolverStatus southwell(const RadiositySystem& system, const FormFactorRowProvider& rows, RgbField& B,
                       const SolverOptions& options, const IterationSink& sink) {
  return shoot(system, rows ? &rows : nullptr, false, B, options, sink);
}

SolverStatus progressiveRefinement(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                                   const IterationSink& sink, const FormFactorRowProvider& rows) {
  return shoot(system, rows ? &rows : nullptr, options.ambient, B, options, sink);
}

ShootingSolver::ShootingSolver(bool progressive)
    : AlgorithmSolver(progressive ? "progressive" : "southwell", nullptr), progressive_(progressive) {}

RgbField ShootingSolver::solve() {
  return run([this](RgbField& B) {
    const IterationSink sink = [this](IterationRecord r) { onRecord(std::move(r)); };
    const FormFactorRowProvider* rows = rows_ ? &rows_ : nullptr;
    return shoot(*system_, rows, progressive_ && options_.ambient, B, options_, sink);
  });
}

}  // namespace rt
