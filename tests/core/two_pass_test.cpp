// The two-pass point query: direct light exact where nothing can block (Lambert's formula, no rays, no
// error), shadow rays where something can, and the final gather from a solution; checked against the path
// tracer on a room with a block that casts shadows on the floor.
#include <gtest/gtest.h>

#include <cmath>

#include "core/formfactor/analytic.h"
#include "core/pathtrace/path_tracer.h"
#include "core/pathtrace/two_pass.h"
#include "core/pipeline/pipeline.h"
#include "formfactor_scenes.h"

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

}  // namespace
}  // namespace rt
