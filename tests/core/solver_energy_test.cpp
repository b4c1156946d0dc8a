// Energy balance at the solution: everything emitted is either absorbed by a surface or escapes through an
// opening.
#include <gtest/gtest.h>

#include "core/solvers/direct_solver.h"
#include "core/solvers/energy.h"
#include "core/solvers/solver.h"
#include "support/test_systems.h"

namespace rt {
namespace {

void expectBalanced(const RadiositySystem& system, const RgbField& B, double tolerance) {
  const Rgb emitted = emittedPower(system);
  const Rgb absorbed = absorbedPower(system, B);
  const Rgb escaped = escapedPower(system, B);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(absorbed(c) + escaped(c), emitted(c), tolerance * emitted(c)) << "channel " << c;
  }
}

TEST(EnergyBalance, ClosedSystemAbsorbsEverything) {
  const test::OwnedSystem s = test::colouredCube();
  RgbField B;
  ASSERT_EQ(directSolve(s.system, B, {}), SolverStatus::Success);
  expectBalanced(s.system, B, 1e-9);
  EXPECT_LT(escapedPower(s.system, B).abs().maxCoeff(), 1e-12 * emittedPower(s.system).maxCoeff());
  EXPECT_NEAR(emittedPower(s.system)(0), 10.0, 1e-15);
}

TEST(EnergyBalance, OpenSystemLosesThroughTheOpening) {
  const test::OwnedSystem s = test::openBox();
  RgbField B;
  ASSERT_EQ(directSolve(s.system, B, {}), SolverStatus::Success);
  expectBalanced(s.system, B, 1e-9);
  EXPECT_GT(escapedPower(s.system, B).minCoeff(), 0.1 * emittedPower(s.system).minCoeff());
}

TEST(EnergyBalance, RandomReciprocalSystem) {
  const test::OwnedSystem s = test::randomSystem(40, 3);
  RgbField B;
  ASSERT_EQ(directSolve(s.system, B, {}), SolverStatus::Success);
  expectBalanced(s.system, B, 1e-9);
}

TEST(EnergyBalance, IterativeSolversAtTightTolerance) {
  for (auto* make : {&test::colouredCube, &test::openBox}) {
    const test::OwnedSystem s = make();
    for (const std::string name : {"jacobi", "gauss-seidel", "southwell", "progressive", "bounces"}) {
      auto solver = makeSolver(name);
      SolverOptions o;
      o.tolerance = 1e-13;
      o.maxIterations = 100000;
      o.recordHistory = false;
      solver->setOptions(o);
      const RgbField B = solver->compute(s.system).solve();
      ASSERT_EQ(solver->info(), SolverStatus::Success) << name;
      SCOPED_TRACE(name);
      expectBalanced(s.system, B, 1e-9);
    }
  }
}

TEST(EnergyBalance, AbsorbedUsesIncidentLightNotEmission) {
  // A single emitter that reflects nothing and sees nothing: it absorbs nothing, everything escapes.
  test::OwnedSystem s;
  s.set(FormFactorMatrix::Zero(1, 1));
  s.system.areas = Eigen::VectorXd::Constant(1, 2.0);
  s.system.reflectance = RgbField::Constant(1, 3, 0.5);
  s.system.emission = RgbField::Constant(1, 3, 3.0);
  const RgbField B = s.system.emission;
  EXPECT_EQ(absorbedPower(s.system, B).sum(), 0.0);
  EXPECT_DOUBLE_EQ(escapedPower(s.system, B)(1), 6.0);
}

}  // namespace
}  // namespace rt
