// The two variance reductions of the line-tracing solvers, against the direct solution of F by quadrature
// (named: the test does not depend on the default method): the constant control variate leaves the mean
// over seeds where it was and lowers the spread on the Cornell box, open and closed; Sobol lines give a
// smaller error than random ones at equal rays; and neither option computes a form factor.
#include <gtest/gtest.h>

#include <cmath>

#include "core/formfactor/formfactor_method.h"
#include "core/io/scene_loader.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/line_shooting.h"
#include "core/solvers/sampling_study.h"
#include "core/solvers/solver.h"
#include "core/solvers/solver_support.h"
#include "support/test_paths.h"

namespace rt {
namespace {

struct Box {
  Mesh mesh;
  RgbField reference;
  explicit Box(const std::string& scene) {
    MeshOptions options;
    options.mode = MeshOptions::Mode::Count;
    options.count = 2;
    mesh = buildMesh(loadScene(test::sourcePath(scene)), options);
    FormFactorStats stats;
    const FormFactorMatrix F = makeFormFactorMethod("quadrature")->compute(mesh, {}, noProgress(), stats);
    EXPECT_EQ(directSolve(RadiositySystem::fromMesh(mesh, F), reference, {}), SolverStatus::Success);
  }
};

const Box& openBox() {
  static const Box box("scenes/cornell-box.json");
  return box;
}
const Box& closedBox() {
  static const Box box("scenes/cornell-box-closed.json");
  return box;
}

RgbField solve(const Box& box, const std::string& solver, std::uint64_t seed, bool control,
               LineSampling sampling = LineSampling::Random) {
  auto s = makeSolver(solver);
  SolverOptions o;
  o.raysPerIteration = 20000;
  o.tolerance = solver == "local-lines" ? 1e-4 : 0.01;
  o.seed = seed;
  o.controlVariate = control;
  o.sampling = sampling;
  o.recordHistory = false;
  s->setOptions(o);
  const RadiositySystem system = RadiositySystem::fromGeometry(box.mesh);
  RgbField B = s->compute(system).solve();
  EXPECT_EQ(s->info(), SolverStatus::Success);
  return B;
}

double errorOf(const Box& box, const RgbField& B) {
  return solver_detail::relativeAreaRms(B - box.reference, box.reference, box.mesh.areas());
}

struct Spread {
  double meanError = 0;  // the error of the mean over the seeds
  double rms = 0;        // RMS over the seeds of each run's error
};

Spread spread(const Box& box, const std::string& solver, bool control, int seeds) {
  RgbField sum = RgbField::Zero(box.reference.rows(), 3);
  double squares = 0;
  for (int s = 1; s <= seeds; ++s) {
    const RgbField B = solve(box, solver, std::uint64_t(s), control);
    sum += B;
    squares += std::pow(errorOf(box, B), 2);
  }
  return {errorOf(box, sum / seeds), std::sqrt(squares / seeds)};
}

TEST(ControlVariate, TheAreaWeightedMedianIsTheConstantOfLeastShotPower) {
  RgbField B(4, 3);
  B << 1, 10, 0, 2, 20, 0, 3, 30, 0, 100, 40, 0;
  const Eigen::VectorXd areas = Eigen::Vector4d(1, 1, 3, 1);
  const Eigen::RowVector3d beta = constantControl(B, areas);
  EXPECT_EQ(beta, Eigen::RowVector3d(3, 30, 0));
  auto shot = [&](double b) { return ((B.col(0).array() - b).abs() * areas.array()).sum(); };
  for (double b : {0.0, 1.0, 2.0, 2.9, 3.1, 50.0}) EXPECT_GE(shot(b), shot(beta(0)));
}

TEST(ControlVariate, LeavesTheMeanOverSeedsUnchangedAndLowersTheSpreadOnTheCornellBox) {
  for (const Box* box : {&openBox(), &closedBox()}) {
    for (const char* solver : {"local-lines", "local-lines-regular"}) {
      const int seeds = 16;
      const Spread plain = spread(*box, solver, false, seeds), control = spread(*box, solver, true, seeds);
      SCOPED_TRACE(std::string(solver) + (box == &openBox() ? ", open box" : ", closed box"));
      // Unbiased: the mean of 16 runs is off by about the runs' error / 4, not by a bias.
      EXPECT_LT(control.meanError, 0.5 * control.rms) << "plain mean " << plain.meanError;
      EXPECT_LT(control.rms, plain.rms) << "plain " << plain.rms << ", control variate " << control.rms;
    }
  }
}

TEST(QuasiMonteCarlo, SobolLinesGiveASmallerErrorThanRandomOnesAtEqualRays) {
  const Box& box = openBox();
  double random = 0, sobol = 0;
  const int seeds = 8;
  for (int s = 1; s <= seeds; ++s) {
    random += std::pow(errorOf(box, solve(box, "local-lines", std::uint64_t(s), false)), 2) / seeds;
    sobol +=
        std::pow(errorOf(box, solve(box, "local-lines", std::uint64_t(s), false, LineSampling::Sobol)), 2) /
        seeds;
  }
  EXPECT_LT(std::sqrt(sobol), 0.8 * std::sqrt(random)) << "random " << std::sqrt(random);
}

TEST(SamplingStudy, RefusesASolverWithoutTheOptionsAndFitsTheSlopes) {
  const Box& box = openBox();
  const RadiositySystem system = RadiositySystem::fromGeometry(box.mesh);
  SamplingStudyOptions o;
  o.raysPerIteration = {2000, 8000, 32000};
  o.seeds = 3;
  o.base.tolerance = 1e-4;
  o.solver = "random-walk";
  EXPECT_THROW(runSamplingStudy(system, box.reference, o), std::invalid_argument);
  o.solver = "local-lines";
  const auto series = runSamplingStudy(system, box.reference, o);
  ASSERT_EQ(series.size(), 3u);
  EXPECT_NEAR(series[0].slope, -0.5, 0.15);            // plain Monte Carlo
  EXPECT_LT(series[2].slope, series[0].slope - 0.05);  // Sobol lines converge faster
  for (const SamplingSeries& s : series) EXPECT_GT(s.points.back().rays, s.points.front().rays);
}

TEST(SamplingStudy, ComparesAtEqualRaysWithTheRowSumsCounted) {
  SamplingSeries plain, variant;
  plain.points.push_back({.rays = 100, .error = 0.1});
  plain.slope = -0.5;
  variant.points.push_back({.rays = 100, .rowSumRays = 300, .error = 0.04});
  // Plain Monte Carlo at 400 rays: 0.1 / 2.
  EXPECT_NEAR(errorRatioAtEqualRays(plain, variant), 0.8, 1e-12);
  EXPECT_NEAR(errorRatioAtEqualRays(plain, plain), 1.0, 1e-12);
  EXPECT_EQ(errorRatioAtEqualRays(plain, SamplingSeries{}), 0.0);
}

// Where the control variate pays most: the closed box, whose radiosities are alike once the light has spread,
// with regular stochastic Jacobi, which shoots the whole B every iteration (Dutré, Bekaert and Bala 2006,
// sec. 6.4). It wins at equal rays even with its row sums' rays counted.
TEST(ControlVariate, WinsAtEqualRaysOnTheClosedBoxWithRegularJacobi) {
  const Box& box = closedBox();
  SamplingStudyOptions o;
  o.solver = "local-lines-regular";
  o.raysPerIteration = {5000, 20000};
  o.seeds = 4;
  o.base.tolerance = 1e-4;
  o.base.maxIterations = 50;  // every variant the same iterations, so the same rays
  const auto series = runSamplingStudy(RadiositySystem::fromGeometry(box.mesh), box.reference, o);
  ASSERT_EQ(series.size(), 3u);
  ASSERT_TRUE(series[1].variant.controlVariate);
  EXPECT_EQ(series[1].points.back().rays, series[0].points.back().rays);
  EXPECT_LT(errorRatioAtEqualRays(series[0], series[1]), 0.85)
      << "plain " << series[0].points.back().error << ", control variate " << series[1].points.back().error;
}

}  // namespace
}  // namespace rt
