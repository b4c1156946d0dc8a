// What distinguishes the solvers from each other: bounce terms, the ambient term, rows on demand,
// Gauss-Seidel's speed-up over Jacobi, seeds, and the two random-walk estimators.
#include <gtest/gtest.h>

#include <cmath>

#include "core/solvers/bounces_solver.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/gathering_solvers.h"
#include "core/solvers/shooting_solvers.h"
#include "core/solvers/stochastic_solvers.h"
#include "support/test_systems.h"

namespace rt {
namespace {

TEST(Bounces, TermsArePowersOfRhoFAndHistoryHoldsPartialSums) {
  const test::OwnedSystem s = test::furnaceCube(0.5, 1.0);
  BouncesSolver solver;
  SolverOptions o;
  o.tolerance = 1e-3;
  solver.setOptions(o);
  const RgbField B = solver.compute(s.system).solve();
  const auto& terms = solver.bounceTerms();
  ASSERT_EQ(terms.size(), solver.history().size() + 1);
  for (std::size_t k = 0; k < terms.size(); ++k) EXPECT_NEAR(terms[k](2, 1), std::pow(0.5, double(k)), 1e-15);
  for (std::size_t k = 1; k < terms.size(); ++k)
    EXPECT_NEAR(solver.history()[k - 1].B(0, 0), (1 - std::pow(0.5, double(k + 1))) / 0.5, 1e-14);
  EXPECT_EQ(solver.history().back().B, B);
}

TEST(Shooting, RowsOnDemandGiveTheMatrixAnswer) {
  const test::OwnedSystem s = test::randomSystem(25, 8);
  SolverOptions o;
  o.tolerance = 1e-12;
  o.maxIterations = 100000;
  RgbField withMatrix, withRows;
  ASSERT_EQ(southwell(s.system, withMatrix, o), SolverStatus::Success);
  RadiositySystem noMatrix = s.system;
  noMatrix.F = nullptr;
  ShootingSolver solver(false);
  solver.setOptions(o);
  solver.setRowProvider([&](int i, std::span<double> row) {
    Eigen::Map<Eigen::RowVectorXd>(row.data(), s.F->cols()) = s.F->row(i);
  });
  withRows = solver.compute(noMatrix).solve();
  EXPECT_EQ(solver.info(), SolverStatus::Success);
  EXPECT_LT((withRows - withMatrix).norm(), 1e-10 * withMatrix.norm());
  EXPECT_EQ(solver.history().front().shooter, 0);  // the brightest emitter shoots first
}

TEST(Shooting, TheDefaultCapScalesWithTheElements) {
  // 700 elements: a fixed cap of 1000 shots is less than two sweeps' worth; the automatic cap (100 shots per
  // element) lets Southwell reach a tight tolerance and the direct solution.
  const test::OwnedSystem s = test::randomSystem(700, 3);
  SolverOptions o;
  o.tolerance = 1e-10;
  ASSERT_EQ(o.maxIterations, 0);
  EXPECT_EQ(shotCap(o, 700), 70000);
  EXPECT_EQ(sweepCap(o), 1000);
  RgbField shot, exact;
  ASSERT_EQ(southwell(s.system, shot, o), SolverStatus::Success);
  ASSERT_EQ(directSolve(s.system, exact, o, {}), SolverStatus::Success);
  EXPECT_LT((shot - exact).norm(), 1e-8 * exact.norm());
  o.maxIterations = 1000;  // the old fixed cap stops far from it
  EXPECT_EQ(southwell(s.system, shot, o), SolverStatus::NoConvergence);
}

TEST(Shooting, AmbientTermFollowsCohenEtAl) {
  const test::OwnedSystem s = test::colouredCube();
  const RgbField unshot = s.system.emission;
  const Rgb ambient = ambientTerm(s.system, unshot);
  for (int c = 0; c < 3; ++c) {
    const double rhoAverage = s.system.reflectance.col(c).mean();  // equal areas
    EXPECT_NEAR(ambient(c), unshot.col(c).mean() / (1 - rhoAverage), 1e-14);
  }
  // With the ambient term the first displayed picture is much closer to the answer.
  RgbField reference;
  ASSERT_EQ(directSolve(s.system, reference, {}), SolverStatus::Success);
  SolverOptions o;
  o.maxIterations = 1;
  RgbField plain;
  southwell(s.system, plain, o);
  o.ambient = true;
  RgbField withAmbient;
  progressiveRefinement(s.system, withAmbient, o);
  EXPECT_LT((withAmbient - reference).norm(), 0.5 * (plain - reference).norm());
}

TEST(Gathering, GaussSeidelNeedsAboutHalfTheSweepsOfJacobi) {
  const test::OwnedSystem s = test::randomSystem(60, 12, 0.98, 0.8);
  SolverOptions o;
  o.tolerance = 1e-10;
  o.maxIterations = 10000;
  int jacobiSweeps = 0, gaussSeidelSweeps = 0, sorSweeps = 0;
  RgbField B;
  ASSERT_EQ(jacobi(s.system, B, o, [&](IterationRecord r) { jacobiSweeps = r.iteration; }),
            SolverStatus::Success);
  ASSERT_EQ(gaussSeidel(s.system, B, o, [&](IterationRecord r) { gaussSeidelSweeps = r.iteration; }),
            SolverStatus::Success);
  EXPECT_LE(gaussSeidelSweeps, 0.7 * jacobiSweeps);
  o.relaxation = 1.2;
  ASSERT_EQ(gaussSeidel(s.system, B, o, [&](IterationRecord r) { sorSweeps = r.iteration; }),
            SolverStatus::Success);
  EXPECT_GT(sorSweeps, 0);
  o.relaxation = 2.5;
  EXPECT_EQ(gaussSeidel(s.system, B, o), SolverStatus::InvalidInput);
}

TEST(Stochastic, SameSeedSameAnswerOtherSeedOtherNoise) {
  const test::OwnedSystem s = test::colouredCube();
  SolverOptions o;
  o.tolerance = 1e-6;
  o.raysPerIteration = 5000;
  for (auto* f : {&stochasticJacobi, &randomWalk}) {
    if (f == &randomWalk) o.maxIterations = 3;
    RgbField a, b, c;
    f(s.system, a, o, {}, nullptr);
    f(s.system, b, o, {}, nullptr);
    o.seed = 2;
    f(s.system, c, o, {}, nullptr);
    o.seed = 1;
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
  }
}

TEST(Stochastic, BothEstimatorsAndBothSolversAgreeWithinStandardErrors) {
  const test::OwnedSystem s = test::openBox();
  RgbField reference;
  ASSERT_EQ(directSolve(s.system, reference, {}), SolverStatus::Success);
  SolverOptions o;
  o.raysPerIteration = 20000;
  o.tolerance = 1e-8;
  RgbField jacobiB, jacobiSe;
  stochasticJacobi(s.system, jacobiB, o, {}, &jacobiSe);
  o.maxIterations = 5;
  for (auto estimator : {SolverOptions::WalkEstimator::Collision, SolverOptions::WalkEstimator::Absorption}) {
    o.walkEstimator = estimator;
    RgbField walkB, walkSe;
    randomWalk(s.system, walkB, o, {}, &walkSe);
    for (Eigen::Index i = 0; i < walkB.rows(); ++i)
      for (int c = 0; c < 3; ++c) {
        const double combined = std::hypot(jacobiSe(i, c), walkSe(i, c));
        EXPECT_LE(std::abs(walkB(i, c) - jacobiB(i, c)), 3.5 * combined + 1e-12) << i << "," << c;
        EXPECT_LE(std::abs(walkB(i, c) - reference(i, c)), 4.0 * walkSe(i, c) + 1e-12) << i << "," << c;
      }
  }
}

}  // namespace
}  // namespace rt
