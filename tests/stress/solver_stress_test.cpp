// Solvers at the edges: reflectance -> 1, nearly touching plates (F -> 1 both ways), scales 1e-6 and 1e6, and
// a larger random system. Every solver uses double throughout; no path computes in float.
#include <gtest/gtest.h>

#include <cmath>

#include "core/formfactor/formfactor_method.h"
#include "core/mesh.h"
#include "core/polygon.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/energy.h"
#include "core/solvers/gathering_solvers.h"
#include "core/solvers/shooting_solvers.h"
#include "core/solvers/solver.h"
#include "support/test_systems.h"

namespace rt {
namespace {

TEST(SolverStress, ReflectanceVeryCloseToOne) {
  const double rho = 0.9999;
  const test::OwnedSystem s = test::furnaceCube(rho);
  for (const std::string name : {"direct", "gauss-seidel", "southwell"}) {
    auto solver = makeSolver(name);
    SolverOptions o;
    o.tolerance = 1e-13;
    o.maxIterations = 2000000;
    o.recordHistory = false;
    solver->setOptions(o);
    const RgbField B = solver->compute(s.system).solve();
    EXPECT_EQ(solver->info(), SolverStatus::Success) << name;
    EXPECT_NEAR(B(3, 1), 1.0 / (1.0 - rho), 1e-6 / (1.0 - rho)) << name;
  }
}

TEST(SolverStress, ScalesOfEmissionAndLengthGiveTheSameAnswerUpToScale) {
  const test::OwnedSystem base = test::randomSystem(20, 9);
  RgbField reference;
  ASSERT_EQ(directSolve(base.system, reference, {}), SolverStatus::Success);
  for (const std::string& name : solverNames()) {
    if (!test::canSolve(name, base.system)) continue;  // a random enclosure has no geometry to trace
    SolverOptions o;
    const bool walks = name.rfind("random-walk", 0) == 0;
    o.tolerance = walks ? 1e-2 : 1e-11;
    o.maxIterations = walks ? 3 : 100000;
    o.raysPerIteration = 2000;
    o.recordHistory = false;
    auto solveWith = [&](double emissionScale, double areaScale) -> RgbField {
      test::OwnedSystem s = test::randomSystem(20, 9);
      s.system.emission *= emissionScale;
      s.system.areas *= areaScale;  // lengths scaled by sqrt(areaScale): F is unchanged
      auto solver = makeSolver(name);
      solver->setOptions(o);
      RgbField B = solver->compute(s.system).solve();
      EXPECT_TRUE(B.allFinite());
      return B / emissionScale;
    };
    const RgbField unit = solveWith(1.0, 1.0);
    for (double scale : {1e-6, 1e6}) {
      EXPECT_LT((solveWith(scale, 1.0) - unit).norm(), 1e-9 * unit.norm()) << name << " E x " << scale;
      EXPECT_LT((solveWith(1.0, scale) - unit).norm(), 1e-9 * unit.norm()) << name << " A x " << scale;
    }
  }
}

// Two unit squares facing each other at a tiny distance: each sees almost only the other (F -> 1), so with
// rho = 0.95 light bounces back and forth and rho F has spectral radius close to rho.
Scene nearlyTouchingPlates(double gap) {
  Scene scene;
  scene.name = "nearly touching plates";
  Material light{"light", Rgb::Constant(0.95), Rgb::Constant(1.0)};
  Material wall{"wall", Rgb::Constant(0.95), Rgb::Zero()};
  scene.materials = {light, wall};
  scene.surfaces = {Surface{"bottom", 0}, Surface{"top", 1}};
  Patch bottom, top;
  bottom.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};       // faces +z
  top.vertices = {Vec3(0, 0, gap), Vec3(0, 1, gap), Vec3(1, 1, gap), Vec3(1, 0, gap)};  // faces -z
  bottom.surface = 0;
  top.surface = 1;
  for (Patch* p : {&bottom, &top}) {
    p->normal = newellNormal(p->vertices).normalized();
    p->area = polygonArea(p->vertices);
  }
  scene.patches = {bottom, top};
  return scene;
}

TEST(SolverStress, NearlyTouchingPlatesWithAnalyticFormFactors) {
  for (double gap : {1e-2, 1e-4}) {
    const Scene scene = nearlyTouchingPlates(gap);
    MeshOptions meshOptions;
    meshOptions.mode = MeshOptions::Mode::Count;
    meshOptions.count = 3;
    const Mesh mesh = buildMesh(scene, meshOptions);
    FormFactorStats stats;
    const FormFactorMatrix F =
        makeFormFactorMethod("analytic")->compute(mesh, FormFactorOptions{}, noProgress(), stats);
    ASSERT_TRUE(F.allFinite());
    EXPECT_LE(F.rowwise().sum().maxCoeff(), 1.0 + 1e-9);
    const RadiositySystem system = RadiositySystem::fromMesh(mesh, F);
    RgbField reference;
    ASSERT_EQ(directSolve(system, reference, {}), SolverStatus::Success) << "gap " << gap;
    const Rgb emitted = emittedPower(system);
    EXPECT_NEAR((absorbedPower(system, reference) + escapedPower(system, reference))(0), emitted(0),
                1e-9 * emitted(0));
    for (const std::string name : {"gauss-seidel", "southwell", "jacobi"}) {
      auto solver = makeSolver(name);
      SolverOptions o;
      o.tolerance = 1e-12;
      o.maxIterations = 1000000;
      o.recordHistory = false;
      solver->setOptions(o);
      const RgbField B = solver->compute(system).solve();
      EXPECT_EQ(solver->info(), SolverStatus::Success) << name << " gap " << gap;
      EXPECT_LT((B - reference).norm(), 1e-9 * reference.norm()) << name << " gap " << gap;
    }
  }
}

TEST(SolverStress, LargerRandomSystemAndMatrixFreeShooting) {
  const test::OwnedSystem s = test::randomSystem(600, 4, 0.98, 0.3);
  RgbField reference;
  ASSERT_EQ(directSolve(s.system, reference, {}), SolverStatus::Success);
  SolverOptions o;
  o.tolerance = 1e-11;
  o.maxIterations = 1000000;
  o.recordHistory = false;
  RgbField B;
  EXPECT_EQ(gaussSeidel(s.system, B, o), SolverStatus::Success);
  EXPECT_LT((B - reference).norm(), 1e-9 * reference.norm());
  // Rows on demand: no matrix in the system at all, rows from reciprocity-consistent F.
  RadiositySystem matrixFree = s.system;
  matrixFree.F = nullptr;
  int rowsAsked = 0;
  const FormFactorRowProvider rows = [&](int i, std::span<double> row) {
    ++rowsAsked;
    Eigen::Map<Eigen::RowVectorXd>(row.data(), s.F->cols()) = s.F->row(i);
  };
  RgbField shot;
  EXPECT_EQ(southwell(matrixFree, rows, shot, o), SolverStatus::Success);
  EXPECT_LT((shot - reference).norm(), 1e-9 * reference.norm());
  EXPECT_GT(rowsAsked, 0);
}

}  // namespace
}  // namespace rt
