// Work the solvers skip, and that skipping never changes the answer: black elements gather nothing, elements
// without unshot power are never shot, and a change of the lights re-solves with the cached F.
#include <gtest/gtest.h>

#include <set>

#include "core/formfactor/formfactor_cache.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/shooting_solvers.h"
#include "core/solvers/solver.h"
#include "formfactor_scenes.h"
#include "support/test_systems.h"

namespace rt {
namespace {

TEST(SkipRules, BlackElementsKeepTheirEmissionInEverySolver) {
  test::OwnedSystem s = test::colouredCube();   // face 3 is black
  s.system.emission.row(3) << 0.25, 0.5, 0.75;  // and now emits: B_3 = E_3 exactly, whatever arrives
  for (const std::string& name : solverNames()) {
    auto solver = makeSolver(name);
    SolverOptions o;
    const bool walks = name.rfind("random-walk", 0) == 0 || name == "photon-density";
    const bool averaging = walks || name == "local-lines-regular";
    o.tolerance = averaging ? 1e-2 : 1e-10;
    o.raysPerIteration = 2000;
    o.maxIterations = walks ? 5 : averaging ? 40 : 10000;
    solver->setOptions(o);
    const RgbField B = solver->compute(s.system).solve();
    EXPECT_EQ(B.row(3), s.system.emission.row(3)) << name;
    for (const IterationRecord& r : solver->history())
      EXPECT_EQ(r.B.row(3), s.system.emission.row(3)) << name;
  }
}

TEST(SkipRules, OnlyElementsWithUnshotPowerShoot) {
  // A random enclosure plus two elements nothing reaches: one black, one that sees nobody and nobody sees.
  const test::OwnedSystem base = test::randomSystem(20, 5);
  test::OwnedSystem s;
  FormFactorMatrix F = FormFactorMatrix::Zero(22, 22);
  F.topLeftCorner(20, 20) = *base.F;
  s.set(F);
  s.system.areas = Eigen::VectorXd::Ones(22);
  s.system.areas.head(20) = base.system.areas;
  s.system.reflectance = RgbField::Constant(22, 3, 0.5);
  s.system.reflectance.topRows(20) = base.system.reflectance;
  s.system.reflectance.row(20).setZero();  // black: whatever arrives is absorbed, nothing to shoot
  s.system.emission = RgbField::Zero(22, 3);
  s.system.emission.topRows(20) = base.system.emission;
  // The black element receives light from element 0 (its column), but never reflects any.
  (*s.F)(0, 20) = 0.01;
  (*s.F)(20, 0) = 0.01 * s.system.areas(0);

  RgbField unshotBefore = s.system.emission;
  std::set<int> shooters;
  ShootingSolver solver(false);
  SolverOptions o;
  o.tolerance = 1e-10;
  o.maxIterations = 100000;
  solver.setOptions(o);
  solver.setObserver([&](const IterationRecord& r) {
    shooters.insert(r.shooter);
    EXPECT_GT(unshotBefore.row(r.shooter).sum(), 0.0) << "shot without unshot power: " << r.shooter;
    unshotBefore = r.unshot;
  });
  RadiositySystem rowsOnly = s.system;
  rowsOnly.F = nullptr;
  std::set<int> rowsAsked;
  solver.setRowProvider([&](int i, std::span<double> row) {
    rowsAsked.insert(i);
    Eigen::Map<Eigen::RowVectorXd>(row.data(), s.F->cols()) = s.F->row(i);
  });
  const RgbField B = solver.compute(rowsOnly).solve();
  ASSERT_EQ(solver.info(), SolverStatus::Success);
  EXPECT_EQ(shooters, rowsAsked);
  EXPECT_EQ(rowsAsked.count(20), 0u) << "the black element was shot";
  EXPECT_EQ(rowsAsked.count(21), 0u) << "the element no light reaches was shot";
  RgbField reference;
  ASSERT_EQ(directSolve(s.system, reference, {}), SolverStatus::Success);
  EXPECT_LT((B - reference).norm(), 1e-8 * reference.norm());
}

TEST(SkipRules, ALightChangeResolvesWithTheCachedFormFactors) {
  Scene scene = test::roomWithBlock();
  Mesh mesh = test::meshOf(scene, 2);
  FormFactorCache cache;
  bool hit = true;
  const auto first = cache.get("analytic", mesh, {}, noProgress(), &hit);
  EXPECT_FALSE(hit);
  RgbField before;
  ASSERT_EQ(directSolve(RadiositySystem::fromMesh(mesh, first->F), before, {}), SolverStatus::Success);

  // Twice the light: F comes from the cache, and B doubles (the system is linear in E).
  scene.materials[1].emission *= 2.0;
  refreshMaterials(mesh, scene);
  const auto second = cache.get("analytic", mesh, {}, noProgress(), &hit);
  EXPECT_TRUE(hit);
  EXPECT_EQ(second.get(), first.get());
  RgbField after;
  ASSERT_EQ(directSolve(RadiositySystem::fromMesh(mesh, second->F), after, {}), SolverStatus::Success);
  EXPECT_LT((after - 2.0 * before).norm(), 1e-12 * after.norm());

  // The same answer as computing F again from scratch.
  FormFactorCache fresh;
  const auto recomputed = fresh.get("analytic", mesh, {}, noProgress(), &hit);
  EXPECT_FALSE(hit);
  RgbField again;
  ASSERT_EQ(directSolve(RadiositySystem::fromMesh(mesh, recomputed->F), again, {}), SolverStatus::Success);
  EXPECT_EQ(again, after);
}

TEST(SkipRules, DirectIsChosenForSmallSystems) {
  for (std::size_t n : {1u, 6u, 320u, 3000u}) EXPECT_EQ(chooseSolver(n), "direct") << n;
  EXPECT_NE(chooseSolver(3001), "direct");
}

}  // namespace
}  // namespace rt
