// The two-pass point query: direct light exact (Lambert's formula where nothing can block, less the part of
// the light the blockers hide, cut out exactly, where something can), and the final gather from a solution;
// checked against many shadow rays and against the path tracer on a room with a block that casts shadows on
// the floor.
#include <gtest/gtest.h>

#include <cmath>

#include "core/formfactor/analytic.h"
#include "core/formfactor/sampling.h"
#include "core/io/scene_loader.h"
#include "core/pathtrace/path_tracer.h"
#include "core/pathtrace/two_pass.h"
#include "core/pipeline/pipeline.h"
#include "formfactor_scenes.h"
#include "support/test_paths.h"

namespace rt {
namespace {

PipelineOutput solve(const Scene& scene, int subdivide) {
  PipelineSettings settings;
  settings.mesh.mode = MeshOptions::Mode::Count;
  settings.mesh.count = subdivide;
  settings.method = "raycast";
  settings.formFactors.samples = 64;
  Pipeline pipeline;
  return pipeline.run(scene, settings);
}

TEST(TwoPass, DirectLightIsLambertsFormulaWhereNothingCanBlock) {
  const Scene scene = test::closedBox(1, 1, 1);  // the top (z = 1) emits, nothing inside
  const TracingScene tracing(scene);
  const PipelineOutput solved = solve(scene, 2);
  const TwoPass twoPass(tracing, *solved.mesh, solved.solve.B, solved.F.get());
  TwoPassOptions options;
  for (const Vec3& p : {Vec3(0.5, 0.5, 0), Vec3(0.01, 0.9, 0), Vec3(0.99, 0.99, 0)}) {
    Rgb error;
    const int element = tracing.locate({p, Vec3::UnitZ()});
    ASSERT_GE(element, 0);
    const Rgb H = twoPass.direct({p, Vec3::UnitZ()}, element, options, 0, error);
    const double F = pointToPolygonFormFactor(p, Vec3::UnitZ(), scene.patches[1].vertices);
    EXPECT_NEAR(H(0), F, 1e-14);
    EXPECT_EQ(error(0), 0.0);  // no ray was needed
  }
}

// The furnace cube (every face emits 1 and reflects 0.5, H = 2) by bounces: the two-pass method's direct
// light is exact, 1; its first bounce, the direct light taken at the gather's hits, 0.5; the rest, 0.5.
TEST(TwoPass, FurnaceBreakdownByBounces) {
  const Scene scene = loadScene(test::sourcePath("scenes/furnace-cube.json"));
  const TracingScene tracing(scene);
  const PipelineOutput solved = solve(scene, 2);
  const TwoPass twoPass(tracing, *solved.mesh, solved.solve.B, solved.F.get());
  const std::vector<SurfacePoint> points{{{0.5, 0, 0.5}, {0, 1, 0}}, {{0.03, 0.9, 0.2}, {1, 0, 0}}};
  for (const PointEstimate& e : twoPass.estimate(points, TwoPassOptions{})) {
    EXPECT_NEAR(e.HDirect(0), 1.0, 1e-12);
    EXPECT_NEAR(e.HBounce(0), 0.5, 4 * e.HBounceError(0) + 1e-9);
    EXPECT_NEAR(e.H(0) - e.HDirect(0) - e.HBounce(0), 0.5, 0.02);  // the solution's raycast form factors
  }
}

// Through the block's penumbra and umbra, the direct light is the unoccluded form factor less the hidden
// part's, with no rays and no error; a million shadow rays to uniform points of the light agree within their
// standard error.
TEST(TwoPass, ShadowedDirectLightIsExact) {
  const Scene scene = test::roomWithBlock();  // a unit room, the top emits, a block on the floor
  const TracingScene tracing(scene);
  const PipelineOutput solved = solve(scene, 2);
  const TwoPass twoPass(tracing, *solved.mesh, solved.solve.B, solved.F.get());
  const Patch* light = nullptr;
  for (const Patch& patch : scene.patches)
    if (scene.materialOf(patch).emission(0) > 0) light = &patch;
  ASSERT_NE(light, nullptr);
  const double lightArea = polygonArea(light->vertices);
  const PolygonSampler sampler(light->vertices.data(), static_cast<int>(light->vertices.size()));
  int shadowed = 0;
  for (double x : {0.02, 0.12, 0.2, 0.29, 0.71, 0.8, 0.9}) {
    const Vec3 p(x, 0.47, 0);
    const int element = tracing.locate({p, Vec3::UnitZ()});
    ASSERT_GE(element, 0);
    Rgb error;
    const double H = twoPass.direct({p, Vec3::UnitZ()}, element, TwoPassOptions(), 0, error)(0);
    EXPECT_EQ(error(0), 0.0);
    shadowed += H < 0.95 * pointToPolygonFormFactor(p, Vec3::UnitZ(), light->vertices);
    constexpr int kRays = 1 << 20;
    PairRandom random(3, static_cast<std::uint64_t>(x * 1000), 0);
    double sum = 0, squares = 0;
    for (int k = 0; k < kRays; ++k) {
      const Vec3 y = sampler.point(random.uniform(), random.uniform());
      double f = pointToPointKernel(p, Vec3::UnitZ(), y, light->normal) * lightArea;
      if (f > 0 && !tracing.rays().visible(p, y, element,
                                           tracing.elementOf(static_cast<int>(light - scene.patches.data()))))
        f = 0;
      sum += f;
      squares += f * f;
    }
    const double mean = sum / kRays, sigma = std::sqrt((squares / kRays - mean * mean) / kRays);
    EXPECT_NEAR(H, mean, 4 * sigma + 1e-12) << "x = " << x;
  }
  EXPECT_GE(shadowed, 4);  // the points do lie in the block's shadow
}

TEST(TwoPass, AgreesWithThePathTracerAroundABlock) {
  const Scene scene = test::roomWithBlock();  // a unit room, the top emits, a block on the floor
  const TracingScene tracing(scene);
  const PipelineOutput solved = solve(scene, 10);
  const TwoPass twoPass(tracing, *solved.mesh, solved.solve.B, solved.F.get());
  std::vector<SurfacePoint> points;
  // Floor points along a line through the block's shadow and past its sides.
  for (double x : {0.05, 0.2, 0.29, 0.75, 0.85, 0.95})
    for (double y : {0.1, 0.5, 0.9}) points.push_back({{x, y, 0}, Vec3::UnitZ()});
  points.push_back({{0.5, 0.5, 0.4}, Vec3::UnitZ()});   // the block's top
  points.push_back({{0.3, 0.5, 0.2}, -Vec3::UnitX()});  // its side
  TwoPassOptions options;
  const auto estimates = twoPass.estimate(points, options);
  const PathTracer tracer(scene);
  PathTraceOptions reference;
  reference.samples = 32768;
  const auto traced = tracer.estimate(points, reference);
  for (std::size_t p = 0; p < points.size(); ++p) {
    ASSERT_GE(estimates[p].element, 0);
    const double sigma = std::hypot(estimates[p].HError(0), traced[p].HError(0));
    // The gathered solution's mesh error (0.1 elements) stays within a percent and a half of H.
    EXPECT_LE(std::abs(estimates[p].H(0) - traced[p].H(0)), 4 * sigma + 0.015 * traced[p].H(0))
        << "point " << p << " (" << points[p].position.transpose() << "): two-pass " << estimates[p].H(0)
        << " +- " << estimates[p].HError(0) << ", path traced " << traced[p].H(0) << " +- "
        << traced[p].HError(0);
  }
}

// On a mesh of 0.5-unit elements the floor's direct light varies by a factor of two across one element; the
// secondary gather takes it at the points its rays reach, so the coarse mesh only enters the light that has
// bounced twice, and the answer stays within two percent of the path tracer.
TEST(TwoPass, ACoarseSolutionStillGivesThePathTracersAnswer) {
  const Scene scene = test::roomWithBlock();
  const TracingScene tracing(scene);
  const PipelineOutput solved = solve(scene, 2);
  const TwoPass twoPass(tracing, *solved.mesh, solved.solve.B, solved.F.get());
  std::vector<SurfacePoint> points;
  for (double x : {0.1, 0.5, 0.9}) points.push_back({{x, 0.9, 0}, Vec3::UnitZ()});
  points.push_back({{0.02, 0.5, 0.5}, Vec3::UnitX()});  // a wall
  const auto estimates = twoPass.estimate(points, TwoPassOptions{});
  PathTraceOptions reference;
  reference.samples = 32768;
  const auto traced = PathTracer(scene).estimate(points, reference);
  for (std::size_t p = 0; p < points.size(); ++p) {
    const double sigma = std::hypot(estimates[p].HError(0), traced[p].HError(0));
    EXPECT_LE(std::abs(estimates[p].H(0) - traced[p].H(0)), 4 * sigma + 0.02 * traced[p].H(0))
        << "point " << p << ": two-pass " << estimates[p].H(0) << " +- " << estimates[p].HError(0)
        << ", path traced " << traced[p].H(0) << " +- " << traced[p].HError(0);
  }
}

// Padding: each further dimension of a batch is a jittered grid of its own, its strata in a shuffled order,
// so that every stratum holds exactly one sample and the dimensions do not line up.
TEST(PaddedStrata, EveryDimensionFillsEachStratumOnce) {
  PairRandom random(7, 1, 2);
  constexpr int kSamples = 64;  // an 8 x 8 grid
  const PaddedStrata strata(kSamples, 3, random);
  int sameCell = 0;
  for (int d = 0; d < 3; ++d) {
    std::vector<int> hits(kSamples, 0);
    for (int k = 0; k < kSamples; ++k) {
      const Vec2 uv = strata.sample(d, k, random);
      const int cell = static_cast<int>(uv.y() * 8) * 8 + static_cast<int>(uv.x() * 8);
      ++hits[static_cast<std::size_t>(cell)];
      if (d == 1) {
        const Vec2 first = strata.sample(0, k, random);
        sameCell += static_cast<int>(first.y() * 8) * 8 + static_cast<int>(first.x() * 8) == cell;
      }
    }
    for (int h : hits) EXPECT_EQ(h, 1) << "dimension " << d;
  }
  EXPECT_LT(sameCell, 8);                           // shuffled, not the same order in every dimension
  const Vec2 beyond = strata.sample(3, 0, random);  // an unpadded dimension: plain uniform
  EXPECT_GE(beyond.x(), 0.0);
  EXPECT_LT(beyond.x(), 1.0);
}

}  // namespace
}  // namespace rt
