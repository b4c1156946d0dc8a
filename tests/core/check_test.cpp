// The invariant checks (core/check.h): on in the test builds, they turn a broken contract into a
// CheckFailure naming the place, and valid work passes them.
#include <gtest/gtest.h>

#include "core/check.h"
#include "core/formfactor/formfactor_matrix.h"
#include "core/formfactor/formfactor_method.h"
#include "core/io/scene_loader.h"
#include "core/mesh.h"
#include "core/progress.h"
#include "core/solvers/radiosity_system.h"
#include "core/solvers/solver.h"
#include "support/test_paths.h"

namespace rt {
namespace {

TEST(Checks, AreOnInTheTestBuilds) {
  EXPECT_TRUE(checksEnabled()) << "configure with RT_CHECKS=ON (the dev and asan presets do)";
}

TEST(Checks, OnePassGivesEveryRowsSumAndThePairsThatSeeEachOther) {
  FormFactorMatrix F = FormFactorMatrix::Zero(3, 3);
  F(0, 1) = 0.25, F(0, 2) = 0.5, F(2, 0) = 0.125;
  const RowSums rows = sumRows(F);
  ASSERT_EQ(rows.sums.size(), 3);
  EXPECT_EQ(rows.sums[0], 0.75);
  EXPECT_EQ(rows.sums[1], 0.0);
  EXPECT_EQ(rows.sums[2], 0.125);
  EXPECT_EQ(rows.positive, 3u);
}

TEST(Checks, RowSumAboveTheBoundIsACheckFailure) {
  if (!checksEnabled()) GTEST_SKIP() << "checks are off in this build";
  FormFactorMatrix F = FormFactorMatrix::Zero(2, 2);
  F(1, 0) = 1.5;
  try {
    checkRowSumsAtMost(sumRows(F), 1.0, "hemicube");
    ADD_FAILURE();
  } catch (const CheckFailure& e) {
    EXPECT_NE(std::string(e.what()).find("internal check failed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("hemicube: row 1 of F sums to 1.5"), std::string::npos) << e.what();
  }
}

TEST(Checks, ShippedScenesPassEveryCheckThroughMeshFormFactorsAndSolve) {
  // The checks sit in buildMesh (planar convex elements), the hemicube and Monte Carlo methods (row sums)
  // and every solver (finite B): a full run on real scenes exercises all of them.
  for (const char* name :
       {"scenes/cornell-box.obj", "scenes/furnace-cube.json", "scenes/occluded-plates.json"}) {
    const Scene scene = loadScene(test::sourcePath(name));
    MeshOptions options;
    options.mode = MeshOptions::Mode::Count;
    options.count = 2;
    const Mesh mesh = buildMesh(scene, options);
    for (const char* method : {"hemicube", "montecarlo"}) {
      FormFactorStats stats;
      FormFactorOptions ff;
      ff.hemicubeResolution = 32;
      ff.samples = 64;
      const FormFactorMatrix F = makeFormFactorMethod(method)->compute(mesh, ff, noProgress(), stats);
      const RadiositySystem system = RadiositySystem::fromMesh(mesh, F);
      for (const std::string& solver : solverNames()) {
        auto s = makeSolver(solver);
        SolverOptions so;
        so.maxIterations = 50;
        so.raysPerIteration = 5000;
        so.recordHistory = false;
        s->setOptions(so);
        EXPECT_NO_THROW(s->compute(system).solve()) << name << " " << method << " " << solver;
      }
    }
  }
}

}  // namespace
}  // namespace rt
