#include "core/solvers/stochastic_solvers.h"

#include "core/solvers/random_walks.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rt {

namespace {

using namespace solver_detail;

// Inclusive running sums of the rows of F, built the first time a row is used as a distribution.
class RowSampler {
 public:
  explicit RowSampler(const FormFactorMatrix& F) : F_(F), cumulative_(static_cast<std::size_t>(F.rows())) {}
  // Element hit by a line leaving `from`, or -1 when it escapes.
  int sample(Eigen::Index from, double u) {
    std::vector<double>& c = cumulative_[static_cast<std::size_t>(from)];
    if (c.empty()) {
      c.resize(static_cast<std::size_t>(F_.cols()));
      double sum = 0.0;
      for (Eigen::Index k = 0; k < F_.cols(); ++k)
        c[static_cast<std::size_t>(k)] = sum += std::max(0.0, F_(from, k));
    }
    const std::size_t k = sampleCumulative(c, u);
    return k < c.size() ? static_cast<int>(k) : -1;
  }

 private:
  const FormFactorMatrix& F_;
  std::vector<std::vector<double>> cumulative_;
};

// Discrete walks: the next element drawn from the row of F of the one the walk stands on.
class RowJumps : public WalkJumps {
 public:
  explicit RowJumps(const FormFactorMatrix& F) : rows_(F) {}
  WalkPosition start(int source, Random&) override { return {source, Vec3::Zero()}; }
  WalkPosition jump(const WalkPosition& from, Random& random) override {
    return {rows_.sample(from.element, random.uniform()), Vec3::Zero()};
  }

 private:
  RowSampler rows_;
};

}  // namespace

SolverStatus stochasticJacobi(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                              const IterationSink& sink, RgbField* standardError) {
  B = system.emission;
  const SolverStatus valid = validate(system, true);
  const auto n = static_cast<Eigen::Index>(system.size());
  RgbField variance = RgbField::Zero(n, 3);
  if (standardError) *standardError = variance;
  if (valid != SolverStatus::Success) return valid;
  const Eigen::VectorXd& A = system.areas;
  const Stopwatch clock;
  Random random(options.seed);
  RowSampler lines(*system.F);
  const long budget = defaultWalks(system, options);

  RgbField unshot = system.emission;
  const double emitted = totalEmittedPower(system);
  if (emitted <= 0.0) return SolverStatus::Success;
  double absorbed = 0.0, escaped = 0.0;
  long raysSoFar = 0;
  std::vector<double> sourceCumulative(static_cast<std::size_t>(n));
  RgbField received(n, 3), receivedSquares(n, 3);

  for (int k = 1, cap = sweepCap(options); k <= cap; ++k) {
    double total = 0.0;
    for (Eigen::Index j = 0; j < n; ++j)
      sourceCumulative[std::size_t(j)] = total += unshot.row(j).sum() * A(j);
    if (total <= 0.0) return SolverStatus::Success;
    // Constant power per ray: later iterations, with less to shoot, get fewer rays.
    // The shrink by 1e-12 keeps the count independent of the units: scaling E or A changes total / emitted in
    // its last bits, which must not change the number of rays (and with it every random number after).
    const long rays =
        std::max(1L, static_cast<long>(std::ceil(double(budget) * (total / emitted) * (1.0 - 1e-12))));
    received.setZero();
    receivedSquares.setZero();
    for (long r = 0; r < rays; ++r) {
      const std::size_t picked = sampleCumulative(sourceCumulative, random.uniform() * total);
      const auto j = static_cast<Eigen::Index>(std::min(picked, std::size_t(n - 1)));
      const double sourcePower = unshot.row(j).sum() * A(j);
      if (sourcePower <= 0.0) continue;  // rounding at the top of the cumulative sum
      // Unbiased weight: the source's power divided by (rays * probability of picking it).
      const Eigen::RowVector3d weight = unshot.row(j) * A(j) * (total / (double(rays) * sourcePower));
      const int hit = lines.sample(j, random.uniform());
      if (hit < 0) {
        escaped += weight.sum();
        continue;
      }
      received.row(hit) += weight;
      receivedSquares.row(hit) += weight.cwiseProduct(weight);
    }
    raysSoFar += rays;
    // Variance of a sum of `rays` independent scores, estimated from the same scores.
    const RgbField sumVariance =
        (receivedSquares.array() - received.array().square() / double(rays)).cwiseMax(0.0).matrix();
    for (Eigen::Index j = 0; j < n; ++j) {
      const Eigen::Array3d rho = system.reflectance.row(j).array().transpose();
      const Eigen::Array3d in = received.row(j).array().transpose();
      absorbed += ((1.0 - rho) * in).sum();
      const Eigen::Array3d gain = rho * in / A(j);
      unshot.row(j) = gain.matrix().transpose();
      B.row(j) += gain.matrix().transpose();
      variance.row(j) +=
          (rho.square() * sumVariance.row(j).array().transpose() / (A(j) * A(j))).matrix().transpose();
    }
    IterationRecord rec;
    rec.iteration = k;
    rec.B = B;
    rec.unshot = unshot;
    rec.unshotPower = unshot.rowwise().sum().cwiseProduct(A).sum();
    rec.emittedPower = emitted;
    rec.absorbedPower = absorbed;
    rec.escapedPower = escaped;
    rec.residual = system.relativeResidual(B);
    rec.standardError = relativeAreaRms(variance.cwiseSqrt(), B, A);
    rec.rays = raysSoFar;
    rec.seconds = clock.seconds();
    const bool done = rec.unshotPower <= options.tolerance * emitted;
    if (standardError) *standardError = variance.cwiseSqrt();
    if (sink) sink(std::move(rec));
    if (done) return SolverStatus::Success;
  }
  return SolverStatus::NoConvergence;
}

SolverStatus randomWalk(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                        const IterationSink& sink, RgbField* standardError) {
  B = system.emission;
  const SolverStatus valid = validate(system, true);
  if (standardError) *standardError = RgbField::Zero(static_cast<Eigen::Index>(system.size()), 3);
  if (valid != SolverStatus::Success) return valid;
  RowJumps jumps(*system.F);
  return walkSolve(system, B, options, sink, standardError, jumps, defaultWalks(system, options));
}

std::unique_ptr<WalkJumps> solver_detail::rowJumps(const FormFactorMatrix& F) {
  return std::make_unique<RowJumps>(F);
}

SolverStatus randomWalkAbsorption(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                                  const IterationSink& sink, RgbField* standardError) {
  SolverOptions absorption = options;
  absorption.walkEstimator = SolverOptions::WalkEstimator::Absorption;
  return randomWalk(system, B, absorption, sink, standardError);
}

StochasticSolver::StochasticSolver(std::string name, Function function)
    : AlgorithmSolver(std::move(name), nullptr), function_(function) {}

RgbField StochasticSolver::solve() {
  return run([this](RgbField& B) {
    return function_(
        *system_, B, options_, [this](IterationRecord r) { onRecord(std::move(r)); }, &standardError_);
  });
}

}  // namespace rt
