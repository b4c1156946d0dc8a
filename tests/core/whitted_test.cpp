// The Whitted ray tracer: its ray counts against the cost formula, shadow acne and light leaks against its
// self-intersection epsilon, and the penumbra its shadow rays draw against the light's size.
#include <gtest/gtest.h>

#include <cmath>

#include "core/io/scene_loader.h"
#include "core/raytrace/ray_cost.h"
#include "core/raytrace/whitted.h"
#include "formfactor_scenes.h"
#include "support/test_paths.h"

namespace rt {
namespace {

std::vector<int> allSurfaces(const Scene& scene) {
  std::vector<int> all;
  for (std::size_t s = 0; s < scene.surfaces.size(); ++s) all.push_back(static_cast<int>(s));
  return all;
}

// In a closed room of mirrors every ray reaches a surface and every hit reflects: the counts are the full
// ray tree's, pixel by pixel and kind by kind. (The room is watertight: a room whose walls meet in
// T-junctions, as the Cornell box's ceiling around its light, lets a rare ray slip between two polygons.)
TEST(Whitted, RayCountsMatchTheCostFormula) {
  Scene scene = test::roomWithBlock();
  scene.camera = Camera{{0.5, 0.05, 0.6}, {0.5, 0.9, 0.3}, {0, 0, 1}, 70};
  const TracingScene tracing(scene);
  for (const int depth : {0, 1, 3}) {
    WhittedOptions options;
    options.depth = depth;
    options.shadowRays = 4;
    options.pixelSamples = 2;
    options.epsilon = 1e-4 * tracing.rays().sceneSize();
    options.mirrorSurfaces = allSurfaces(scene);
    const WhittedTracer tracer(tracing, options);
    const WhittedImage image = tracer.render(scene.cameraOrDefault(), 16, 12);
    RayCostInputs in;
    in.pixels = 16 * 12;
    in.pixelSamples = 2;
    in.lights = tracer.lights();
    in.shadowRays = 4;
    in.depth = depth;
    const RayCost cost = whittedRayCost(in);
    EXPECT_EQ(static_cast<double>(image.stats.rays.primary), cost.primary) << "depth " << depth;
    EXPECT_EQ(static_cast<double>(image.stats.rays.reflection), cost.secondary) << "depth " << depth;
    EXPECT_EQ(static_cast<double>(image.stats.rays.shadow), cost.shadow) << "depth " << depth;
    EXPECT_EQ(static_cast<double>(image.stats.rays.total()), cost.total) << "depth " << depth;
    // One pixel's tree: a chain of depth + 1 surface hits, each with its shadow rays.
    const RayTree tree = tracer.trace(scene.cameraOrDefault(), 16, 12, 8, 6);
    EXPECT_EQ(static_cast<double>(tree.counts().total()), cost.perPrimaryRay);
    EXPECT_EQ(tree.counts().reflection, static_cast<std::uint64_t>(depth));
  }
}

TEST(Whitted, CostFormulaCountsBinaryTrees) {
  RayCostInputs in;
  in.pixels = 100;
  in.lights = 2;
  in.shadowRays = 3;
  in.depth = 2;
  in.branching = 2;
  const RayCost cost = whittedRayCost(in);
  EXPECT_EQ(cost.treeNodes, 7);            // 1 + 2 + 4
  EXPECT_EQ(cost.perPrimaryRay, 7 * 7.0);  // each node: itself and 2 x 3 shadow rays
  EXPECT_EQ(cost.total, 100 * 49.0);
  EXPECT_EQ(cost.primary + cost.secondary + cost.shadow, cost.total);
}

WhittedStats shadowCheck(const Scene& scene, const TracingScene& tracing, double epsilon) {
  WhittedOptions options;
  options.epsilon = epsilon;
  options.checkShadows = true;
  return WhittedTracer(tracing, options).render(scene.cameraOrDefault(), 64, 64).stats;
}

// With epsilon 0 a shadow ray starts at a hit point that rounding put a hair above or below its surface; from
// below it meets the surface again at once. A proper epsilon removes that, and one as large as a block lets
// the shadow rays of the floor near its base skip the whole block.
TEST(Whitted, EpsilonZeroGivesAcneAndTooLargeLeaks) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
  const TracingScene tracing(scene);
  const double size = tracing.rays().sceneSize();
  const WhittedStats zero = shadowCheck(scene, tracing, 0.0);
  const WhittedStats proper = shadowCheck(scene, tracing, 1e-4 * size);
  const WhittedStats large = shadowCheck(scene, tracing, 0.2 * size);
  EXPECT_GT(zero.lit, 1000u);
  EXPECT_GT(zero.acneFraction(), 0.2) << zero.acne << " of " << zero.lit;
  EXPECT_LT(proper.acneFraction(), 1e-3) << proper.acne << " of " << proper.lit;
  EXPECT_LT(proper.leakFraction(), 1e-3);
  EXPECT_GT(large.leakFraction(), 0.05) << large.leaks << " of " << large.blocked;
}

// A thin shelf a little above the floor: once epsilon exceeds the way up to the shelf, the light leaks under
// it and its shadow vanishes, while a proper epsilon keeps it whole.
TEST(Whitted, TooLargeEpsilonLetsLightUnderAThinBlocker) {
  Scene s = test::emptyScene();
  test::addQuad(s, {-0.2, -0.2, 2}, {-0.2, 0.2, 2}, {0.2, 0.2, 2}, {0.2, -0.2, 2}, true);
  test::addQuad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0});
  test::addQuad(s, {-0.5, -0.5, 0.05}, {-0.5, 0.5, 0.05}, {0.5, 0.5, 0.05}, {0.5, -0.5, 0.05});
  const TracingScene tracing(s);
  // Floor points under the shelf and around it.
  auto check = [&](double epsilon) {
    WhittedOptions options;
    options.epsilon = epsilon;
    options.checkShadows = true;
    const WhittedTracer tracer(tracing, options);
    WhittedStats stats;
    for (double x = -0.8; x <= 0.8; x += 0.05)
      for (double y = -0.8; y <= 0.8; y += 0.05)
        tracer.directIrradiance({x, y, 0}, tracing.elementOf(1), stats);
    return stats;
  };
  const WhittedStats proper = check(1e-4), large = check(0.1);
  EXPECT_GT(proper.blocked, 100u);
  EXPECT_EQ(proper.leaks, 0u);
  EXPECT_GT(large.leakFraction(), 0.9) << large.leaks << " of " << large.blocked;
}

// A square light 2 above the floor, a half-plane blocker at height 1 whose edge lies over x = 0: the shadow's
// edge on the floor is a penumbra about as wide as the light (similar triangles), and a point light's is a
// step.
Scene penumbraScene(bool blocker) {
  Scene s = test::emptyScene();
  test::addQuad(s, {-0.2, -0.2, 2}, {-0.2, 0.2, 2}, {0.2, 0.2, 2}, {0.2, -0.2, 2}, true);
  test::addQuad(s, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0});
  if (blocker) test::addQuad(s, {-1, -1, 1}, {-1, 1, 1}, {0, 1, 1}, {0, -1, 1});
  return s;
}

// Width of the floor's 10 %-90 % visibility ramp along y = 0.
double penumbraWidth(int shadowRays, double lightScale) {
  const Scene open = penumbraScene(false), shaded = penumbraScene(true);
  const TracingScene a(open), b(shaded);
  WhittedOptions options;
  options.shadowRays = shadowRays;
  options.lightScale = lightScale;
  options.epsilon = 1e-6;
  const WhittedTracer lit(a, options), shadowed(b, options);
  double low = 0, high = 0;
  for (double x = -0.8; x <= 0.8; x += 0.005) {
    WhittedStats stats;
    const Vec3 p(x, 0, 0);
    const double v = shadowed.directIrradiance(p, b.elementOf(1), stats)(0) /
                     lit.directIrradiance(p, a.elementOf(1), stats)(0);
    if (v < 0.1) low = x;
    if (v < 0.9) high = x;
  }
  return high - low;
}

TEST(Whitted, SoftShadowPenumbraGrowsWithTheLight) {
  const double hard = penumbraWidth(1, 1), small = penumbraWidth(256, 1), large = penumbraWidth(256, 2);
  EXPECT_LE(hard, 0.0051);
  EXPECT_NEAR(small, 0.8 * 0.4, 0.03);  // a square light's ramp is linear: 10 %-90 % is 0.8 of its side
  EXPECT_NEAR(large, 0.8 * 0.8, 0.05);
  EXPECT_GT(large, 1.7 * small);
}

}  // namespace
}  // namespace rt
