// The furnace: a closed cube, every face with the same reflectance and emission, has B = E / (1 - rho)
// exactly, whatever the form factors (rows sum to 1). As rho -> 1 the system approaches a singular one and
// iterations slow down like rho^k: every solver must either reach the answer or say NoConvergence with a
// finite residual.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "core/solvers/solver.h"
#include "support/test_systems.h"

namespace rt {
namespace {

// Solvers that report a per-element error instead of reaching the exact solution: the stochastic ones (a
// standard error) and hierarchical-clustering (an error estimate: its links approximate F).
bool isStochastic(const std::string& name) {
  return name == "stochastic-jacobi" || name.rfind("random-walk", 0) == 0 || name == "local-lines" ||
         name == "local-lines-regular" || name == "hierarchical-clustering" || name == "photon-density";
}

class Furnace : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(Furnace, ReachesEOverOneMinusRho) {
  const auto& [name, rho] = GetParam();
  const double E = 2.0;
  const test::OwnedSystem s = test::furnaceCube(rho, E);
  const double expected = E / (1.0 - rho);
  auto solver = makeSolver(name);
  SolverOptions o;
  o.recordHistory = false;
  o.tolerance = 1e-12;
  o.maxIterations = 200000;
  if (name == "stochastic-jacobi" || name == "local-lines") {
    o.tolerance = 1e-6;
    // Rays per iteration scale with the unshot power, so the total is about budget / (1 - rho).
    o.raysPerIteration = rho >= 0.99 ? 2000 : 20000;
  } else if (name == "local-lines-regular") {
    // The burn-in lasts until rho^k <= tolerance, then the mean's relative standard error must reach it.
    o.tolerance = rho >= 0.99 ? 2e-2 : 3e-3;
    o.raysPerIteration = 2000;
  } else if (name.rfind("random-walk", 0) == 0 || name == "photon-density") {
    // Relative standard error; walks get 1 / (1 - rho) steps long, so the near-singular cases ask for less.
    o.tolerance = rho >= 0.99 ? 2e-2 : 3e-3;
    o.raysPerIteration = rho >= 0.99 ? 2000 : 20000;
    o.maxIterations = 100;
  }
  solver->setOptions(o);
  const RgbField B = solver->compute(s.system).solve();
  ASSERT_TRUE(B.allFinite());
  EXPECT_TRUE(std::isfinite(solver->error()));
  EXPECT_EQ(solver->info(), SolverStatus::Success)
      << toString(solver->info()) << " after " << solver->iterations();
  if (isStochastic(name)) {
    const RgbField& se = solver->standardError();
    ASSERT_EQ(se.rows(), 6);
    for (Eigen::Index i = 0; i < 6; ++i)
      for (int c = 0; c < 3; ++c) {
        EXPECT_GT(se(i, c), 0.0);
        EXPECT_LE(std::abs(B(i, c) - expected), 4.0 * se(i, c)) << "element " << i << " channel " << c;
      }
    EXPECT_LT((B.array() / expected - 1.0).abs().maxCoeff(), 0.05);
  } else {
    // A residual of 1e-12 bounds the error by 1e-12 * cond(K) ~ 1e-12 * 2 / (1 - rho).
    EXPECT_LT((B.array() / expected - 1.0).abs().maxCoeff(), 1e-11 / (1.0 - rho)) << B;
  }
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, Furnace,
                         ::testing::Combine(::testing::ValuesIn(solverNames()),
                                            ::testing::Values(0.5, 0.9, 0.99, 0.999)),
                         [](const ::testing::TestParamInfo<Furnace::ParamType>& info) {
                           std::string name = std::get<0>(info.param);
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name + "_rho" +
                                  std::to_string(static_cast<int>(std::get<1>(info.param) * 1000));
                         });

TEST(FurnaceCap, JacobiStopsWithFiniteResidualAndAnUnderestimate) {
  const test::OwnedSystem s = test::furnaceCube(0.999);
  auto solver = makeSolver("jacobi");
  SolverOptions o;
  o.maxIterations = 100;
  solver->setOptions(o);
  const RgbField B = solver->compute(s.system).solve();
  EXPECT_EQ(solver->info(), SolverStatus::NoConvergence);
  EXPECT_EQ(solver->iterations(), 100);
  EXPECT_TRUE(std::isfinite(solver->error()));
  // Jacobi from B = E adds one bounce per sweep: after 100 sweeps B = sum_{k<=100} rho^k, far below 1000.
  const double partial = (1.0 - std::pow(0.999, 101)) / (1.0 - 0.999);
  EXPECT_NEAR(B(0, 0), partial, 1e-9 * partial);
  EXPECT_NEAR(solver->error(), std::pow(0.999, 101), 1e-9);  // residual = the next bounce
}

TEST(FurnaceCap, ReflectanceOneIsSingularButNeverNaN) {
  const test::OwnedSystem s = test::furnaceCube(1.0);
  for (const std::string& name : solverNames()) {
    auto solver = makeSolver(name);
    SolverOptions o;
    o.maxIterations = 5;
    o.raysPerIteration = 20;
    solver->setOptions(o);
    const RgbField B = solver->compute(s.system).solve();
    EXPECT_TRUE(B.allFinite()) << name;
    EXPECT_TRUE(std::isfinite(solver->error())) << name;
    if (name == "direct") {
      EXPECT_EQ(solver->info(), SolverStatus::NumericalIssue) << name;
    } else {
      EXPECT_EQ(solver->info(), SolverStatus::NoConvergence) << name << ": " << toString(solver->info());
    }
  }
}

}  // namespace
}  // namespace rt
