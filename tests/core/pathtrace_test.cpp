// The path tracer against known answers: the furnace (B = E / (1 - rho) in a closed cube of one material),
// direct light against Lambert's exact point-to-polygon form factor, the radiosity solution of a finely
// meshed cube, and a standard error that falls like 1 / sqrt(samples).
#include <gtest/gtest.h>

#include <cmath>

#include "core/formfactor/analytic.h"
#include "core/io/scene_loader.h"
#include "core/pathtrace/path_tracer.h"
#include "core/pipeline/pipeline.h"
#include "formfactor_scenes.h"
#include "support/test_paths.h"

namespace rt {
namespace {

std::vector<SurfacePoint> cubePoints() {
  return {{{0.5, 0, 0.5}, {0, 1, 0}},    // floor centre
          {{0.02, 0, 0.97}, {0, 1, 0}},  // floor corner
          {{0, 0.5, 0.5}, {1, 0, 0}},    // wall centre
          {{0.5, 1, 0.2}, {0, -1, 0}},   // ceiling
          {{1, 0.1, 0.9}, {-1, 0, 0}}};
}

TEST(PathTracer, FurnaceGivesEOverOneMinusRho) {
  const Scene scene = loadScene(test::sourcePath("scenes/furnace-cube.json"));
  const PathTracer tracer(scene);
  PathTraceOptions options;
  options.samples = 4096;
  const auto estimates = tracer.estimate(cubePoints(), options);
  for (std::size_t p = 0; p < estimates.size(); ++p) {
    const PointEstimate& e = estimates[p];
    ASSERT_GE(e.element, 0) << "point " << p;
    for (int c = 0; c < 3; ++c) {
      EXPECT_GT(e.BError(c), 0.0);
      EXPECT_LT(e.BError(c), 0.01);  // 4096 paths give well under a percent
      EXPECT_LE(std::abs(e.B(c) - 2.0), 4 * e.BError(c)) << "point " << p << " channel " << c;
      EXPECT_LE(std::abs(e.H(c) - 2.0), 4 * e.HError(c));  // H = sum_j F_ij B_j = 2 as well
    }
  }
}

// The furnace's H = 2 by bounces: every face emits 1 and the faces close the cube, so the direct light is 1,
// the first bounce rho = 0.5 and the rest 0.5.
TEST(PathTracer, FurnaceBreakdownByBounces) {
  const Scene scene = loadScene(test::sourcePath("scenes/furnace-cube.json"));
  const PathTracer tracer(scene);
  PathTraceOptions options;
  options.samples = 4096;
  for (const PointEstimate& e : tracer.estimate(cubePoints(), options))
    for (int c = 0; c < 3; ++c) {
      EXPECT_LE(std::abs(e.HDirect(c) - 1.0), 4 * e.HDirectError(c) + 1e-12);
      EXPECT_LE(std::abs(e.HBounce(c) - 0.5), 4 * e.HBounceError(c));
      EXPECT_LE(std::abs(e.H(c) - e.HDirect(c) - e.HBounce(c) - 0.5), 4 * e.HError(c));
    }
}

TEST(PathTracer, FurnaceImageIsUniform) {
  const Scene scene = loadScene(test::sourcePath("scenes/furnace-cube.json"));
  const PathTracer tracer(scene);
  Camera camera{{0.5, 0.5, 0.95}, {0.4, 0.45, 0}, {0, 1, 0}, 70};
  PathTraceOptions options;
  options.samples = 64;
  const TracedImage image = tracer.render(camera, 16, 12, options);
  int within = 0;
  for (std::size_t k = 0; k < image.B.pixels.size(); ++k)
    within += std::abs(image.B.pixels[k](0) - 2.0) <= 4 * image.error.pixels[k](0) + 1e-12;
  // Every pixel sees a face from inside; 4 sigma covers all but a rare few.
  EXPECT_GE(within, static_cast<int>(image.B.pixels.size()) - 1);
  EXPECT_GT(image.rays, 16u * 12 * 64);
}

// Black walls and a black emitter: what arrives is the emitter's direct light only, E F(x -> light).
TEST(PathTracer, DirectLightMatchesLambertsFormula) {
  Scene scene = test::emptyScene();
  scene.materials[0].reflectance = Rgb::Zero();
  scene.materials[1].reflectance = Rgb::Zero();
  scene.materials[1].emission = Rgb(3, 2, 1);
  test::addQuad(scene, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});  // receiver, faces +z
  test::addQuad(scene, {0.2, 0.1, 0.8}, {0.2, 0.9, 0.8}, {0.9, 0.9, 0.8}, {0.9, 0.1, 0.8}, true);  // faces -z
  const PathTracer tracer(scene);
  const std::vector<SurfacePoint> points{
      {{0.5, 0.5, 0}, {0, 0, 1}}, {{0.05, 0.95, 0}, {0, 0, 1}}, {{0.99, 0.01, 0}, {0, 0, 1}}};
  PathTraceOptions options;
  options.samples = 8192;
  const auto estimates = tracer.estimate(points, options);
  for (std::size_t p = 0; p < points.size(); ++p) {
    const double F =
        pointToPolygonFormFactor(points[p].position, points[p].normal, scene.patches[1].vertices);
    for (int c = 0; c < 3; ++c) {
      const double expected = scene.materials[1].emission(c) * F;
      EXPECT_LE(std::abs(estimates[p].H(c) - expected), 4 * estimates[p].HError(c) + 1e-12)
          << "point " << p << " channel " << c << " expected " << expected;
      EXPECT_LT(estimates[p].HError(c), 0.01 * expected);
    }
    EXPECT_EQ(estimates[p].B.matrix().norm(), 0.0);  // black receiver reflects nothing
  }
}

// The same integral equation solved by radiosity on a fine mesh (exact form factors of a convex room):
// the two agree at element centroids to the mesh's error, a fraction of a percent at this size.
TEST(PathTracer, AgreesWithTheRadiositySolutionOfAFineMesh) {
  const Scene scene = loadScene(test::sourcePath("scenes/furnace-cube-one-light.json"));
  PipelineSettings settings;
  settings.mesh.mode = MeshOptions::Mode::Count;
  settings.mesh.count = 16;
  settings.method = "analytic";
  Pipeline pipeline;
  const PipelineOutput solved = pipeline.run(scene, settings);
  const Mesh& mesh = *solved.mesh;
  std::vector<SurfacePoint> points;
  std::vector<int> elements;
  for (std::size_t e = 0; e < mesh.size(); e += 97) {
    points.push_back({mesh.elements[e].centroid, mesh.elements[e].normal});
    elements.push_back(static_cast<int>(e));
  }
  ASSERT_GE(points.size(), 8u);
  const PathTracer tracer(scene);
  PathTraceOptions options;
  options.samples = 16384;
  const auto estimates = tracer.estimate(points, options);
  for (std::size_t p = 0; p < points.size(); ++p) {
    const double radiosity = solved.solve.B(elements[p], 0);
    const double traced = estimates[p].B(0);
    EXPECT_LE(std::abs(traced - radiosity), 4 * estimates[p].BError(0) + 0.005 * radiosity)
        << "element " << elements[p] << ": path traced " << traced << " +- " << estimates[p].BError(0)
        << ", radiosity " << radiosity;
  }
}

// A closed box of six patches, each with its own reflectance (per channel) and the emission E_i = b (1 -
// rho_i) that makes the radiosity b the same everywhere: there B is uniform on every patch, so the direct
// solve on the six patches has no meshing error and gives b exactly, and the path tracer, with no mesh, must
// agree with it at any point of any face within its standard error.
TEST(PathTracer, AgreesWithTheDirectSolveOfSixUniformPatches) {
  Scene scene;
  test::addBox(scene, Vec3::Zero(), Vec3(1, 1.5, 0.8), false);
  const Rgb b(2, 3, 4);
  const Rgb reflectances[6] = {{0.1, 0.5, 0.8}, {0.7, 0.2, 0.4}, {0.3, 0.3, 0.9},
                               {0.6, 0.8, 0.1}, {0.0, 0.4, 0.5}, {0.9, 0.1, 0.3}};
  for (int f = 0; f < 6; ++f) {
    const std::string name = "face" + std::to_string(f);
    scene.materials.push_back({name, reflectances[f], b * (1 - reflectances[f])});
    scene.surfaces.push_back({name, f});
    scene.patches[static_cast<std::size_t>(f)].surface = f;
  }
  PipelineSettings settings;
  settings.mesh.mode = MeshOptions::Mode::None;
  settings.method = "analytic";
  settings.solver = "direct";
  Pipeline pipeline;
  const PipelineOutput solved = pipeline.run(scene, settings);
  ASSERT_EQ(solved.mesh->size(), 6u);
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(solved.solve.B(f, c), b(c), 1e-9) << "face " << f;

  std::vector<SurfacePoint> points;
  for (const Patch& patch : scene.patches)
    for (const Vec2& uv : {Vec2(0.5, 0.5), Vec2(0.05, 0.1), Vec2(0.9, 0.97)}) {
      const Vec3 p = patch.vertices[0] + uv.x() * (patch.vertices[1] - patch.vertices[0]) +
                     uv.y() * (patch.vertices[3] - patch.vertices[0]);
      points.push_back({p, patch.normal});
    }
  const PathTracer tracer(scene);
  PathTraceOptions options;
  options.samples = 4096;
  const auto estimates = tracer.estimate(points, options);
  for (std::size_t p = 0; p < points.size(); ++p)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(estimates[p].B(c), b(c), 4 * estimates[p].BError(c) + 1e-9)
          << "point " << p << " (" << points[p].position.transpose() << "), channel " << c;
}

TEST(PathTracer, StandardErrorFallsLikeOneOverSqrtSamples) {
  const Scene scene = loadScene(test::sourcePath("scenes/furnace-cube-one-light.json"));
  const PathTracer tracer(scene);
  const std::vector<SurfacePoint> points{{{0.3, 0, 0.6}, {0, 1, 0}}, {{0, 0.4, 0.5}, {1, 0, 0}}};
  PathTraceOptions few, many;
  few.samples = 512;
  many.samples = 16 * 512;
  const auto a = tracer.estimate(points, few);
  const auto b = tracer.estimate(points, many);
  for (std::size_t p = 0; p < points.size(); ++p) {
    // 16 times the samples: a quarter of the error, give or take the noise of an error measured from 32
    // batches (about 13 % each).
    const double ratio = a[p].HError(0) / b[p].HError(0);
    EXPECT_GT(ratio, 2.8) << "point " << p;
    EXPECT_LT(ratio, 5.7) << "point " << p;
  }
}

// The benchmark scene is the published box closed by a front wall: from anywhere inside, every ray meets the
// front of a polygon (nothing escapes, no back face shows through a gap).
// The closed box and its variants with the light hung below an uncut ceiling (0.1 mm and 1 cm).
TEST(PathTracer, ClosedCornellBoxLetsNoRayEscape) {
  for (const char* file : {"cornell-box-closed.json", "cornell-box-closed-light-0.1mm.json",
                           "cornell-box-closed-light-1cm.json"}) {
    SCOPED_TRACE(file);
    const Scene scene = loadScene(test::sourcePath(std::string("scenes/") + file));
    const TracingScene tracing(scene);
    PairRandom random(11, 0, 0);
    int escaped = 0, backFaces = 0, rays = 0;
    for (int k = 0; k < 20000; ++k) {
      // Points in the air of the room, above the tall block so that none lies inside a block, and below the
      // lowest light, whose back only the ceiling sees.
      const Vec3 origin(20 + 510 * random.uniform(), 340 + 190 * random.uniform(),
                        20 + 520 * random.uniform());
      const Vec3 direction = cosineDirection(Vec3::UnitY(), random.uniform(), random.uniform()) *
                             (random.uniform() < 0.5 ? 1.0 : -1.0);
      const RayHit hit = tracing.rays().firstHit(origin, direction.normalized(), -1);
      ++rays;
      escaped += hit.element < 0;
      backFaces += hit.element >= 0 && !hit.frontSide;
    }
    EXPECT_EQ(escaped, 0);
    EXPECT_EQ(backFaces, 0);
    EXPECT_EQ(rays, 20000);
  }
}

TEST(PathTracer, SameSeedSameAnswer) {
  const Scene scene = loadScene(test::sourcePath("scenes/furnace-cube-one-light.json"));
  const PathTracer tracer(scene);
  PathTraceOptions options;
  options.samples = 256;
  const auto a = tracer.estimate(cubePoints(), options);
  const auto b = tracer.estimate(cubePoints(), options);
  options.seed = 2;
  const auto c = tracer.estimate(cubePoints(), options);
  EXPECT_EQ(a[0].H(0), b[0].H(0));
  EXPECT_NE(a[0].H(0), c[0].H(0));
}

}  // namespace
}  // namespace rt
