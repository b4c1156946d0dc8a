// The walks recordWalks returns are the walks the walk solvers follow: with the same options they carry the
// power the solver reports for its first batch (absorbed and escaped), their collision scores make the
// solver's B after that batch, a longer recording begins with a shorter one, and the two discrete
// estimators follow the same walks. A photon's landings lie on the elements it landed on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/formfactor/formfactor_method.h"
#include "core/io/scene_loader.h"
#include "core/mesh.h"
#include "core/progress.h"
#include "core/solvers/random_walks.h"
#include "core/solvers/stochastic_solvers.h"
#include "support/test_paths.h"

namespace rt {
namespace {

struct Box {
  Mesh mesh;
  FormFactorMatrix F;
};

const Box& cornell() {
  static const Box box = [] {
    const Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
    MeshOptions o;
    o.mode = MeshOptions::Mode::Count;
    o.count = 2;
    Box b{buildMesh(scene, o), {}};
    FormFactorStats stats;
    b.F = makeFormFactorMethod("quadrature")->compute(b.mesh, FormFactorOptions{}, noProgress(), stats);
    return b;
  }();
  return box;
}

SolverOptions walkOptions(long walks) {
  SolverOptions o;
  o.seed = 11;
  o.raysPerIteration = walks;
  o.maxIterations = 1;
  o.recordHistory = true;
  return o;
}

// The first iteration's record of a solver run with batches of `walks`.
IterationRecord firstBatch(const std::string& solver, const RadiositySystem& system, long walks) {
  IterationRecord first;
  const IterationSink sink = [&first](IterationRecord rec) {
    if (rec.iteration == 1) first = std::move(rec);
  };
  RgbField B;
  const SolverOptions o = walkOptions(walks);
  if (solver == "photon-density")
    photonDensity(system, B, o, sink);
  else
    randomWalk(system, B, o, sink);
  return first;
}

void expectTheSolversWalks(const std::string& solver, const RadiositySystem& system) {
  constexpr long kWalks = 300;
  std::vector<RecordedWalk> walks;
  ASSERT_EQ(recordWalks(solver, system, walkOptions(kWalks), kWalks, walks), SolverStatus::Success);
  ASSERT_EQ(walks.size(), std::size_t(kWalks));
  const IterationRecord first = firstBatch(solver, system, kWalks);
  ASSERT_EQ(first.rays, kWalks);

  double absorbed = 0, escaped = 0;
  const Eigen::VectorXd& A = system.areas;
  RgbField B = system.emission;
  std::size_t landings = 0;
  for (const RecordedWalk& walk : walks) {
    absorbed += walk.absorbedPower;
    escaped += walk.escapedPower;
    ASSERT_EQ(walk.points.size(), walk.landings.size() + 1);
    ASSERT_EQ(walk.weights.size(), walk.landings.size());
    for (std::size_t k = 0; k < walk.landings.size(); ++k) {
      const auto j = static_cast<Eigen::Index>(walk.landings[k]);
      B.row(j) += walk.weights[k].cwiseProduct(system.reflectance.row(j)) / (double(kWalks) * A(j));
    }
    landings += walk.landings.size();
  }
  EXPECT_GT(landings, std::size_t(kWalks)) << "walks go on after their first landing";
  EXPECT_NEAR(absorbed / kWalks, first.absorbedPower, 1e-9 * first.emittedPower);
  EXPECT_NEAR(escaped / kWalks, first.escapedPower, 1e-9 * first.emittedPower);
  EXPECT_LT((B - first.B).cwiseAbs().maxCoeff(), 1e-9 * first.B.cwiseAbs().maxCoeff())
      << "the collision scores of the recorded walks are the solver's B after its first batch";

  // The first walks of a larger batch are these.
  std::vector<RecordedWalk> more;
  ASSERT_EQ(recordWalks(solver, system, walkOptions(kWalks), 2 * kWalks, more), SolverStatus::Success);
  for (std::size_t w = 0; w < walks.size(); ++w) EXPECT_EQ(more[w].landings, walks[w].landings);
}

TEST(WalkRecording, DiscreteWalksAreTheOnesTheCollisionEstimatorScores) {
  const Box& box = cornell();
  expectTheSolversWalks("random-walk", RadiositySystem::fromMesh(box.mesh, box.F));
}

TEST(WalkRecording, PhotonsAreTheOnesThePhotonDensityCounts) {
  expectTheSolversWalks("photon-density", RadiositySystem::fromGeometry(cornell().mesh));
}

TEST(WalkRecording, BothDiscreteEstimatorsFollowTheSameWalksDrawnBetweenCentroids) {
  const Box& box = cornell();
  const RadiositySystem system = RadiositySystem::fromMesh(box.mesh, box.F);
  std::vector<RecordedWalk> collision, absorption;
  ASSERT_EQ(recordWalks("random-walk", system, walkOptions(50), 50, collision), SolverStatus::Success);
  ASSERT_EQ(recordWalks("random-walk-absorption", system, walkOptions(50), 50, absorption),
            SolverStatus::Success);
  ASSERT_EQ(collision.size(), absorption.size());
  for (std::size_t w = 0; w < collision.size(); ++w) {
    EXPECT_EQ(collision[w].landings, absorption[w].landings);
    for (std::size_t k = 0; k < collision[w].landings.size(); ++k)
      EXPECT_EQ(collision[w].points[k + 1], box.mesh.elements[collision[w].landings[k]].centroid);
  }
}

TEST(WalkRecording, PhotonsLandOnTheElementsTheyScore) {
  const Mesh& mesh = cornell().mesh;
  std::vector<RecordedWalk> walks;
  ASSERT_EQ(recordWalks("photon-density", RadiositySystem::fromGeometry(mesh), walkOptions(100), 100, walks),
            SolverStatus::Success);
  // On the element's plane within the ray tracer's single-precision rounding of the box's size.
  double size = 0;
  for (const Vec3& v : mesh.vertices) size = std::max(size, v.cwiseAbs().maxCoeff());
  for (const RecordedWalk& walk : walks)
    for (std::size_t k = 0; k < walk.landings.size(); ++k) {
      const Element& e = mesh.elements[walk.landings[k]];
      EXPECT_LT(std::abs(e.normal.normalized().dot(walk.points[k + 1] - e.centroid)), 1e-6 * size);
    }
}

TEST(WalkRecording, RefusesOtherSolversAndMissingInput) {
  const Mesh& mesh = cornell().mesh;
  std::vector<RecordedWalk> walks;
  EXPECT_EQ(recordWalks("jacobi", RadiositySystem::fromMesh(mesh, cornell().F), walkOptions(10), 10, walks),
            SolverStatus::InvalidInput);
  EXPECT_EQ(recordWalks("random-walk", RadiositySystem::fromGeometry(mesh), walkOptions(10), 10, walks),
            SolverStatus::InvalidInput);
  EXPECT_TRUE(walks.empty());
}

}  // namespace
}  // namespace rt
