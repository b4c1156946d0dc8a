// One contract, every registered solver: it converges to the direct solution, calls the observer once per
// iteration, keeps a consistent history, and reports NoConvergence (never an exception, never NaN) when the
// cap is hit.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "core/pipeline/linear_solve.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/energy.h"
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

// Options under which each solver should reach the direct solution on a small system.
SolverOptions convergingOptions(const std::string& name) {
  SolverOptions o;
  o.tolerance = 1e-12;
  o.maxIterations = 100000;
  if (name == "stochastic-jacobi" || name == "local-lines") {
    o.tolerance = 1e-9;
    o.raysPerIteration = 200000;
  }
  if (name == "local-lines-regular") {
    o.tolerance = 3e-3;  // the burn-in's bound rho_max^k and then the relative standard error of the mean
    o.raysPerIteration = 200000;
    o.maxIterations = 1000;
  }
  if (name.rfind("random-walk", 0) == 0 || name == "photon-density") {
    o.tolerance = 2e-3;  // relative standard error
    o.raysPerIteration = 20000;
    o.maxIterations = 200;
  }
  return o;
}

RgbField directSolution(const RadiositySystem& system) {
  RgbField B;
  EXPECT_EQ(directSolve(system, B, {}), SolverStatus::Success);
  return B;
}

class SolverContract : public ::testing::TestWithParam<std::string> {};

TEST_P(SolverContract, ConvergesToDirectSolution) {
  const auto random30 = [] { return test::randomSystem(30, 7); };
  // The last system is the linear basis's nodes: only the solvers it names take it (the pipeline refuses
  // the others with the reason).
  const std::vector<std::function<test::OwnedSystem()>> systems{test::colouredCube, test::openBox, random30,
                                                                test::colouredCubeLinear};
  for (std::size_t k = 0; k < systems.size(); ++k) {
    if (k + 1 == systems.size() && !linearBasisSolves(GetParam())) continue;
    const test::OwnedSystem s = systems[k]();
    const RgbField reference = directSolution(s.system);
    auto solver = makeSolver(GetParam());
    if (!test::canSolve(GetParam(), s.system)) {
      // A solver that traces rays cannot run on a matrix alone, and says so.
      solver->compute(s.system).solve();
      EXPECT_EQ(solver->info(), SolverStatus::InvalidInput);
      continue;
    }
    EXPECT_EQ(solver->name(), GetParam());
    solver->setOptions(convergingOptions(GetParam()));
    const RgbField B = solver->compute(s.system).solve();
    EXPECT_EQ(solver->info(), SolverStatus::Success) << toString(solver->info());
    ASSERT_EQ(B.rows(), reference.rows());
    ASSERT_TRUE(B.allFinite());
    if (isStochastic(GetParam())) {
      const RgbField& se = solver->standardError();
      ASSERT_EQ(se.rows(), B.rows());
      // Aggregate agreement in units of the reported standard error (elements with no noise excluded).
      double chi = 0;
      int count = 0;
      for (Eigen::Index i = 0; i < B.rows(); ++i)
        for (int c = 0; c < 3; ++c)
          if (se(i, c) > 0) {
            chi += std::pow((B(i, c) - reference(i, c)) / se(i, c), 2);
            ++count;
          } else {
            EXPECT_NEAR(B(i, c), reference(i, c), 1e-12 * reference.norm());
          }
      ASSERT_GT(count, 0);
      if (GetParam() == "photon-density") {
        // Continuous walks solve the integral equation, not this constant-element system: on these whole
        // faces the two differ by the discretisation (1-2 %), more than the noise.
        EXPECT_LT((B - reference).norm() / reference.norm(), 0.03);
        continue;
      }
      EXPECT_LE(std::sqrt(chi / count), 3.0);
      EXPECT_LT((B - reference).norm() / reference.norm(), 0.01);
    } else {
      EXPECT_LT((B - reference).norm() / reference.norm(), 1e-9);
    }
  }
}

TEST_P(SolverContract, ObserverOncePerIterationAndHistoryConsistent) {
  const test::OwnedSystem s = test::colouredCube();
  auto solver = makeSolver(GetParam());
  SolverOptions o = convergingOptions(GetParam());
  solver->setOptions(o);
  int calls = 0;
  solver->setObserver([&](const IterationRecord& r) {
    ++calls;
    EXPECT_EQ(r.iteration, calls);
  });
  const RgbField B = solver->compute(s.system).solve();
  EXPECT_GT(calls, 0);
  EXPECT_EQ(calls, solver->iterations());
  const auto& history = solver->history();
  ASSERT_EQ(static_cast<int>(history.size()), calls);
  const double emitted = emittedPower(s.system).sum();
  double previousSeconds = 0;
  for (const IterationRecord& r : history) {
    ASSERT_EQ(r.B.rows(), 6);
    EXPECT_TRUE(r.B.allFinite());
    EXPECT_TRUE(std::isfinite(r.residual));
    EXPECT_GE(r.residual, 0.0);
    EXPECT_NEAR(r.emittedPower, emitted, 1e-12 * emitted);
    EXPECT_GE(r.seconds, previousSeconds);
    previousSeconds = r.seconds;
    if (r.shooter >= 0) {
      EXPECT_LT(r.shooter, 6);
      ASSERT_EQ(r.unshot.rows(), 6);
      // Shooting keeps the books exactly: emitted = absorbed + escaped + still unshot.
      EXPECT_NEAR(r.absorbedPower + r.escapedPower + r.unshotPower, emitted, 1e-9 * emitted);
    }
  }
  EXPECT_EQ(history.back().B, B);
  EXPECT_DOUBLE_EQ(solver->error(), history.back().residual);
  if (!isStochastic(GetParam())) {
    EXPECT_NEAR(history.back().residual, s.system.relativeResidual(B), 1e-12);
  }
}

TEST_P(SolverContract, NoConvergenceStatusOnIterationCap) {
  const test::OwnedSystem s = test::furnaceCube(0.999);
  auto solver = makeSolver(GetParam());
  SolverOptions o;
  o.tolerance = 1e-14;
  o.maxIterations = 3;
  o.raysPerIteration = 100;
  solver->setOptions(o);
  int calls = 0;
  solver->setObserver([&](const IterationRecord&) { ++calls; });
  RgbField B;
  EXPECT_NO_THROW(B = solver->compute(s.system).solve());
  ASSERT_TRUE(B.allFinite());
  EXPECT_TRUE(std::isfinite(solver->error()));
  if (GetParam() == "direct") {
    EXPECT_EQ(solver->info(), SolverStatus::Success);  // not iterative: one step is the answer
  } else {
    EXPECT_EQ(solver->info(), SolverStatus::NoConvergence) << toString(solver->info());
    EXPECT_EQ(solver->iterations(), 3);
    EXPECT_EQ(calls, 3);
    EXPECT_GT(solver->error(), 1e-14);
  }
}

TEST_P(SolverContract, InvalidInputIsAStatus) {
  test::OwnedSystem s = test::colouredCube();
  s.system.reflectance(2, 1) = std::nan("");
  auto solver = makeSolver(GetParam());
  RgbField B;
  EXPECT_NO_THROW(B = solver->compute(s.system).solve());
  EXPECT_EQ(solver->info(), SolverStatus::InvalidInput);
  EXPECT_TRUE(B.allFinite());
}

TEST_P(SolverContract, NoHistoryWhenNotRecorded) {
  const test::OwnedSystem s = test::colouredCube();
  auto solver = makeSolver(GetParam());
  SolverOptions o = convergingOptions(GetParam());
  o.recordHistory = false;
  solver->setOptions(o);
  int calls = 0;
  solver->setObserver([&](const IterationRecord&) { ++calls; });
  solver->compute(s.system).solve();
  EXPECT_TRUE(solver->history().empty());
  EXPECT_EQ(calls, solver->iterations());
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, SolverContract, ::testing::ValuesIn(solverNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST(SolverRegistry, KnowsEveryMethodAndRejectsOthers) {
  EXPECT_EQ(solverNames().size(), 13u);
  EXPECT_FALSE(solverNeedsMatrix("local-lines"));
  EXPECT_FALSE(solverNeedsMatrix("local-lines-regular"));
  EXPECT_FALSE(solverNeedsMatrix("hierarchical-clustering"));
  EXPECT_TRUE(solverNeedsMatrix("stochastic-jacobi"));
  EXPECT_TRUE(solverNeedsMatrix("southwell"));
  for (const std::string& name : solverNames()) EXPECT_EQ(makeSolver(name)->name(), name);
  try {
    makeSolver("conjugate-gradient");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gauss-seidel"), std::string::npos);
  }
  EXPECT_EQ(chooseSolver(100), "direct");
  EXPECT_EQ(chooseSolver(3000), "direct");
  EXPECT_EQ(chooseSolver(3001), "gauss-seidel");
}

}  // namespace
}  // namespace rt
