#include <gtest/gtest.h>

#include <cmath>

#include "core/refine/piece_mesh.h"
#include "core/refine/refine.h"
#include "refine_energy.h"
#include "refine_test_scenes.h"

namespace rt {
namespace {

TEST(RefineAdaptive, ElementsShrinkAtTheShadowBoundaries) {
  RefineOptions o;
  o.mode = RefineMode::Adaptive;
  o.initialMaxEdge = 0.5;
  o.gradientTolerance = 0.3;
  o.maxPasses = 6;
  const RefinedSolution s = solveRefined(test::shadowScene(), o);
  ASSERT_GT(s.stats.elements, s.stats.initialElements);
  // Floor elements whose centre is near a shadow line (|x| or |y| in [0.6, 1.4] while the other is inside the
  // penumbra's extent) against floor elements far out (max(|x|,|y|) > 1.6).
  double nearArea = 0, farArea = 0;
  int nearCount = 0, farCount = 0;
  for (std::size_t e = 0; e < s.mesh.size(); ++e) {
    const Element& el = s.mesh.elements[e];
    if (el.patch != 2) continue;
    const double x = std::abs(el.centroid.x()), y = std::abs(el.centroid.y());
    const double m = std::max(x, y);
    if (m > 0.6 && m < 1.4) nearArea += el.area, ++nearCount;
    if (m > 1.6) farArea += el.area, ++farCount;
  }
  ASSERT_GT(nearCount, 0);
  ASSERT_GT(farCount, 0);
  EXPECT_LT(nearArea / nearCount, 0.25 * farArea / farCount) << s.stats.summary();
  // Only new rows and columns were computed: fewer pairs than recomputing F after every pass.
  std::size_t everything = 0;
  for (const RefinePass& p : s.stats.passes) everything += p.elements * (p.elements - 1) / 2;
  EXPECT_LT(s.stats.pairsComputed, everything);
}

TEST(RefineAdaptive, ClosedRoomConservesEnergyAfterRefinement) {
  RefineOptions o;
  o.mode = RefineMode::Adaptive;
  o.initialMaxEdge = 0.7;
  o.maxPasses = 3;
  o.maxElements = 600;
  const RefinedSolution s = solveRefined(test::closedRoom(), o);
  EXPECT_GT(s.stats.elements, s.stats.initialElements);
  const Eigen::Array3d ratio = test::absorbedOverEmitted(s);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(ratio[c], 1.0, 0.03) << s.stats.summary();
}

TEST(RefineAdaptive, FurnaceStaysUniformAndUnrefined) {
  // Closed room, every surface emitting 1 and reflecting 0.5: B = E / (1 - rho) = 2 everywhere, nothing to
  // refine.
  Scene s = test::closedRoom();
  for (Material& m : s.materials) {
    m.reflectance = Rgb::Constant(0.5);
    m.emission = Rgb::Constant(1.0);
  }
  RefineOptions o;
  o.initialMaxEdge = 0.7;
  const RefinedSolution r = solveRefined(s, o);
  EXPECT_EQ(r.stats.elements, r.stats.initialElements);
  for (Eigen::Index i = 0; i < r.B.rows(); ++i) EXPECT_NEAR(r.B(i, 0), 2.0, 0.06);
}

TEST(RefineAdaptive, TVerticesAreRecordedAndTheDisplayMeshIsConforming) {
  RefineOptions o;
  o.initialMaxEdge = 0.5;
  o.maxPasses = 3;
  const RefinedSolution s = solveRefined(test::shadowScene(), o);
  ASSERT_FALSE(s.tVertices.empty());
  for (const TVertex& t : s.tVertices) {
    const Vec3 expected = (1 - t.t) * s.mesh.vertices[t.edgeStart] + t.t * s.mesh.vertices[t.edgeEnd];
    EXPECT_LT((s.mesh.vertices[t.vertex] - expected).norm(), 1e-9);
  }
  std::vector<int> source;
  const Mesh display = conformingDisplayMesh(s, &source);
  // Same total area per patch, and no hanging vertex left.
  EXPECT_NEAR(display.areas().sum(), s.mesh.areas().sum(), 1e-9);
  EXPECT_TRUE(findTVertices(display).empty());
  ASSERT_EQ(source.size(), display.size());
}

}  // namespace
}  // namespace rt
