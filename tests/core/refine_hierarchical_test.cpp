#include <gtest/gtest.h>

#include "core/refine/refine.h"
#include "refine_test_scenes.h"

namespace rt {
namespace {

TEST(RefineHierarchical, ConvergesToTheFineUniformSolution) {
  // Few visibility rays keep this quick; the reference and the hierarchy share the same transfer kernel.
  const Scene scene = test::closedRoom();
  RefineOptions fine;
  fine.mode = RefineMode::Uniform;
  fine.initialMaxEdge = 0.15;
  fine.visibilitySamples = 4;
  const RefinedSolution reference = solveRefined(scene, fine);

  std::vector<double> errors;
  for (double tolerance : {0.04, 0.015, 0.006}) {
    RefineOptions o;
    o.mode = RefineMode::Hierarchical;
    o.linkTolerance = tolerance;
    o.brightnessWeighted = false;  // the plain F oracle: the error bound shrinks with the tolerance
    o.minArea = 0.15 * 0.15 / 2;
    o.visibilitySamples = 4;
    const RefinedSolution h = solveRefined(scene, o);
    errors.push_back(relativeRmsError(h, reference));
    const double n = static_cast<double>(h.stats.elements);
    EXPECT_LT(static_cast<double>(h.stats.links), 0.25 * n * n) << h.stats.summary();
    EXPECT_EQ(h.links.size(), h.stats.links);
  }
  EXPECT_LT(errors[1], errors[0]);
  EXPECT_LT(errors[2], errors[1]);
  EXPECT_LT(errors[2], 0.1);
}

TEST(RefineHierarchical, LeavesReconstructTheHierarchy) {
  RefineOptions o;
  o.mode = RefineMode::Hierarchical;
  o.linkTolerance = 0.01;
  o.minArea = 0.01;
  const Scene scene = test::shadowScene();
  const RefinedSolution h = solveRefined(scene, o);
  // The leaves tile every patch exactly.
  std::vector<double> area(scene.patches.size(), 0.0);
  for (const Element& e : h.mesh.elements) area[e.patch] += e.area;
  for (std::size_t p = 0; p < scene.patches.size(); ++p) EXPECT_NEAR(area[p], scene.patches[p].area, 1e-9);
  EXPECT_GT(h.stats.maxLevel, 1);
  ASSERT_EQ(h.elementLevel.size(), h.mesh.size());
  // The floor in the umbra gets nothing directly; far from it, plenty.
  EXPECT_LT(radiosityAt(h, 2, Vec3(0, 0, 0))[0], 0.1 * radiosityAt(h, 2, Vec3(1.8, 0, 0))[0]);
}

}  // namespace
}  // namespace rt
