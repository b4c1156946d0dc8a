// The lesson on ray tracing: what its text says about the numbers of its raytrace steps, checked on those
// steps (same scene, same parameters), and what the stage does when a reader changes the tracer's settings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "core/io/rgb_image.h"
#include "core/raytrace/whitted.h"
#include "lesson/step_runner.h"
#include "lesson_test_support.h"

namespace rt::lesson {
namespace {

using Ran = test::RanStep;

// Runs the lesson's step that draws `figure`, with `change` applied to its parameters first.
Ran run(const std::string& figure, const std::function<void(StepParameters&)>& change = {}) {
  return test::runStepWithFigure("ray-tracing", figure, change);
}

TEST(RayTracingLesson, RayCastingSendsOnePrimaryAndOneShadowRay) {
  const Ran r = run("casting");
  EXPECT_EQ(r["tree.shadow"], 1);
  EXPECT_EQ(r["tree.reflection"], 0);
  EXPECT_EQ(r["tree.rays"], 2);
  ASSERT_TRUE(r.result.raytrace);
  EXPECT_EQ(r.result.raytrace->tree.nodes.front().kind, RayKind::Primary);
  EXPECT_GT(r.result.mesh.size(), 0u) << "the app's 3D view has the room to draw the rays in";
}

TEST(RayTracingLesson, ManyShadowRaysSoftenWhatOneLeavesHard) {
  const Ran r = run("shadows");
  const RayTraceData& d = *r.result.raytrace;
  ASSERT_EQ(d.hard.pixels.size(), d.whitted.pixels.size());
  // The soft picture differs from the hard one (its penumbrae), and the light-size control widens them.
  EXPECT_GT(rmsDifference(d.hard, d.whitted), 0.01 * r["mean.whitted"]);
  const Ran larger = run("shadows", [](StepParameters& p) { p.lightSize = 3; });
  EXPECT_GT(rmsDifference(larger.result.raytrace->whitted, d.hard), rmsDifference(d.whitted, d.hard));
  EXPECT_GT(r["shadow-rays"], 1);
}

TEST(RayTracingLesson, TheMirrorsTreeGrowsAndADiffusePixelsStops) {
  const Ran r = run("tree");
  EXPECT_GE(r["tree.reflection"], 1) << "the pixel sees the mirror";
  EXPECT_EQ(r["tree.rays"], 1 + r["tree.reflection"] + r["tree.shadow"]);
  EXPECT_EQ(r["tree.shadow"], (1 + r["tree.reflection"]) * r["lights"] * r["shadow-rays"]);
  EXPECT_LE(r["tree.blocked"], r["tree.shadow"]);
  // The depth limit cuts the tree; without mirrors it stops at the first hit.
  const Ran flat = run("tree", [](StepParameters& p) { p.rayDepth = 0; });
  EXPECT_EQ(flat["tree.reflection"], 0);
  EXPECT_EQ(flat["tree.rays"], 1 + flat["lights"] * flat["shadow-rays"]);
  const Ran diffuse = run("tree", [](StepParameters& p) { p.mirrors.clear(); });
  EXPECT_EQ(diffuse["tree.reflection"], 0);
}

TEST(RayTracingLesson, TheCountedRaysFollowTheCostFormula) {
  const Ran r = run("cost");
  const double nodes = 1 + r["ray-depth"];
  EXPECT_EQ(r["tree-nodes.formula"], nodes);
  EXPECT_EQ(r["rays-per-pixel.formula"], nodes * (1 + r["lights"] * r["shadow-rays"]));
  EXPECT_EQ(r["rays.formula"], r["pixels"] * r["rays-per-pixel.formula"]);
  EXPECT_EQ(r["pixels"], r["image-size"] * r["image-size"]);
  EXPECT_EQ(r["rays.primary"], r["pixels"]);
  EXPECT_EQ(r["rays.total"], r["rays.primary"] + r["rays.shadow"] + r["rays.reflection"]);
  // Every ray that meets a surface sends its shadow rays; a mirror ray leaving by the open front sends none.
  EXPECT_LE(r["rays.shadow"], (r["rays.primary"] + r["rays.reflection"]) * r["lights"] * r["shadow-rays"]);
  EXPECT_LT(r["rays.total"], r["rays.formula"]) << "only the tall block is a mirror";
  EXPECT_GT(r["rays.shadow"], 0.9 * r["rays.total"]) << "shadow rays are nearly all of the work";
  EXPECT_GT(r["seconds.whitted"], 0);
  // The chart: the formula rises by the same step per level, the counts flatten out.
  const RayTraceData& d = *r.result.raytrace;
  ASSERT_GE(d.formula.size(), 4u);
  const double step = d.formula[1] - d.formula[0];
  for (std::size_t k = 1; k < d.formula.size(); ++k) EXPECT_DOUBLE_EQ(d.formula[k] - d.formula[k - 1], step);
  const std::size_t n = d.counted.size();
  EXPECT_LT(d.counted[n - 1] - d.counted[n - 2], 0.1 * (d.counted[1] - d.counted[0]));
  // "Double the shadow rays or the image's side and watch the numbers follow."
  const Ran doubled = run("cost", [](StepParameters& p) { p.imageSize *= 2; });
  EXPECT_EQ(doubled["rays.formula"], 4 * r["rays.formula"]);
}

TEST(RayTracingLesson, EpsilonZeroGivesAcneAProperOneNoneAndABlockHighOneLeaks) {
  const Ran r = run("epsilon");
  EXPECT_GT(r["acne.zero"], 0.2);
  EXPECT_LT(r["acne.step"], 1e-3);
  EXPECT_GT(r["leaks.large"], 0.05);
  // "about a block's height": the short block is 165 mm high, the tall one 330 mm.
  EXPECT_GT(r["epsilon.large"], 150);
  EXPECT_LT(r["epsilon.large"], 350);
  // "the acne disappears long before anything leaks": the good values span orders of magnitude.
  const Ran small = run("epsilon", [](StepParameters& p) { p.rayEpsilon = 0.05; });
  const Ran large = run("epsilon", [](StepParameters& p) { p.rayEpsilon = 20; });
  EXPECT_LT(small["acne.step"], 1e-3);
  EXPECT_LT(large["acne.step"], 1e-3);
  EXPECT_EQ(large["leaks.step"], 0);
  EXPECT_EQ(r["leaks.step"], 0);
}

TEST(RayTracingLesson, TheRayTracerMissesTheLightRadiosityAndPathsFind) {
  const Ran r = run("versus");
  EXPECT_LT(r["ceiling.whitted"], 1e-9) << "black";
  EXPECT_GT(r["ceiling.radiosity"], 0.2 * r["mean.radiosity"]);
  EXPECT_NEAR(r["bleed.whitted"], 1, 1e-3) << "no colour bleeding";
  EXPECT_GT(r["bleed.radiosity"], r["bleed.whitted"] + 0.05) << "redder near the red wall";
  EXPECT_LT(r["mean.whitted"], 0.9 * r["mean.radiosity"]);
  // The path tracer, one more bounce at a time.
  EXPECT_LT(r["ceiling.path.0"], 1e-9) << "direct light only, as Whitted";
  EXPECT_GT(r["ceiling.path.1"], 0.5 * r["ceiling.path.all"]);
  EXPECT_GT(r["ceiling.path.2"], r["ceiling.path.1"]);
  EXPECT_GT(r["ceiling.path.all"], r["ceiling.path.2"]);
  EXPECT_NEAR(r["ceiling.path.all"], r["ceiling.radiosity"], 0.15 * r["ceiling.radiosity"]);
  EXPECT_LT(r["mean.path.2"] - r["mean.path.1"], r["mean.path.1"] - r["mean.path.0"]) << "adds less again";
  EXPECT_GT(r["mean.path.all"], r["mean.path.2"]);
  EXPECT_NEAR(r["floor.path.0"], r["floor.whitted"], 0.05 * r["floor.whitted"]) << "the same direct light";
}

// The glossy figure: the glossy mirror differs from the ideal one, more for a smaller q (a blurrier
// reflection), and not at all for q = 0, the ideal mirror; the gloss control changes the picture.
TEST(RayTracingLesson, GlossyMirrorsBlurWhatIdealOnesReflect) {
  const Ran r = run("glossy");
  ASSERT_TRUE(r.result.raytrace);
  EXPECT_GT(r["gloss"], 0);
  EXPECT_GT(r["gloss-difference"], 0.01) << "the reflection is visibly blurred";
  const Ran blurrier = run("glossy", [](StepParameters& p) { p.gloss = 4; });
  EXPECT_GT(blurrier["gloss-difference"], r["gloss-difference"]);
  EXPECT_GT(rmsDifference(blurrier.result.raytrace->whitted, r.result.raytrace->whitted),
            0.01 * r["mean.whitted"])
      << "the control changes the picture";
  const Ran ideal = run("glossy", [](StepParameters& p) { p.gloss = 0; });
  EXPECT_EQ(ideal["gloss-difference"], 0) << "q = 0 is the ideal mirror";
}

// The rays-per-pixel control: every pixel sends that many primary rays, the counts follow it, and the
// picture changes (jittered edges, averaged lobe).
TEST(RayTracingLesson, RaysPerPixelMultiplyThePrimaryRaysAndSmoothThePicture) {
  const Ran r = run("glossy");
  EXPECT_EQ(r["rays.primary"], r["pixels"] * r["pixel-samples"]);
  const Ran one = run("glossy", [](StepParameters& p) { p.pixelSamples = 1; });
  EXPECT_EQ(one["rays.primary"], one["pixels"]);
  EXPECT_GT(rmsDifference(one.result.raytrace->whitted, r.result.raytrace->whitted),
            0.01 * r["mean.whitted"]);
}

// The focus figure: through the lens the back wall, on the plane of focus, stays as the pinhole drew it,
// while the short block in front blurs; the blur discs follow equation (blur-disc); a lens of radius 0 is the
// pinhole, and focusing on the short block turns the order round.
TEST(RayTracingLesson, TheLensBlursWhatLiesOffThePlaneOfFocus) {
  const Ran r = run("focus");
  ASSERT_TRUE(r.result.raytrace);
  EXPECT_GT(r["aperture"], 0);
  EXPECT_LT(r["blur-disc.back_wall"], 1.0) << "sharp: under a pixel";
  EXPECT_GT(r["blur-disc.short_block"], 3.0) << "blurred over several pixels";
  EXPECT_GT(r["blur-disc.tall_block"], r["blur-disc.back_wall"]);
  EXPECT_LT(r["blur-disc.tall_block"], r["blur-disc.short_block"]);
  const double f = r["focus-distance"], z = r["depth.short_block"], a = r["aperture"];
  const double pixel = 2 * std::tan(r.result.camera.fovYDegrees * std::numbers::pi / 360) / r["image-size"];
  EXPECT_NEAR(r["blur-disc.short_block"], 2 * a * std::abs(1 / f - 1 / z) / pixel, 1e-9);
  EXPECT_GT(r["focus-difference.short_block"], 5 * r["focus-difference.back_wall"]);
  EXPECT_GT(r["focus-difference.short_block"], 5 * r["focus-difference.tall_block"]);
  const Ran pinhole = run("focus", [](StepParameters& p) { p.aperture = 0; });
  EXPECT_EQ(pinhole["focus-difference.short_block"], 0) << "radius 0 is the pinhole";
  EXPECT_EQ(pinhole["blur-disc.short_block"], 0);
  const Ran near = run("focus", [&](StepParameters& p) { p.focusDistance = z; });
  EXPECT_LT(near["blur-disc.short_block"], 0.1);
  EXPECT_GT(near["focus-difference.back_wall"], near["focus-difference.short_block"]);
}

// The motion figure: the short block slides while the shutter is open; its pixels and the floor under its
// shadow differ from the still picture's, the walls far from it not at all; its streak follows equation
// (motion-streak), a motion of 0 is the still picture and a longer motion blurs more.
TEST(RayTracingLesson, AMovingBlockBlursAndTheStandingOnesStaySharp) {
  const Ran r = run("motion");
  ASSERT_TRUE(r.result.raytrace);
  EXPECT_GT(r["motion"], 0);
  const double z = r["depth.short_block"];
  const double pixel = 2 * std::tan(r.result.camera.fovYDegrees * std::numbers::pi / 360) / r["image-size"];
  const Vec3 forward = (r.result.camera.target - r.result.camera.position).normalized();
  const double across = (Vec3(r["motion"], 0, 0) - r["motion"] * forward.x() * forward).norm();
  EXPECT_NEAR(r["motion-pixels.short_block"], across / z / pixel, 1e-9);
  EXPECT_GT(r["motion-pixels.short_block"], 10.0) << "a streak over many pixels";
  EXPECT_GT(r["motion-difference.short_block"], 2 * r["motion-difference.tall_block"]);
  EXPECT_GT(r["motion-difference.short_block"], 0.05);
  EXPECT_GT(r["motion-difference.floor"], 0.05) << "the block's shadow moves with it";
  EXPECT_EQ(r["motion-difference.left_wall"], 0) << "far from the block the pictures agree exactly";
  EXPECT_EQ(r["motion-difference.ceiling"], 0);
  EXPECT_EQ(r["rays.primary"], r["pixels"] * r["pixel-samples"]) << "the time costs no extra rays";
  const Ran still = run("motion", [](StepParameters& p) { p.motion = 0; });
  EXPECT_EQ(still["motion-difference.short_block"], 0) << "motion 0 stands still";
  EXPECT_EQ(still["motion-pixels.short_block"], 0);
  const Ran longer = run("motion", [](StepParameters& p) { p.motion *= 2; });
  EXPECT_NEAR(longer["motion-pixels.short_block"], 2 * r["motion-pixels.short_block"], 1e-9);
  EXPECT_GT(longer["motion-difference.short_block"], r["motion-difference.short_block"]);
}

// A light may not move: the lights stand still in the tracer, so the stage refuses.
TEST(RayTracingLesson, AMovingLightIsRefused) {
  const std::string error =
      test::inputErrorOf([] { run("motion", [](StepParameters& p) { p.moving = "light"; }); });
  EXPECT_NE(error.find("emits light"), std::string::npos) << error;
}

// Equation (lobe-density): directions drawn by cos(alpha) = u^(1/(q+1)) have the Phong lobe's mean cosine,
// (q + 1) / (q + 2), and are unit vectors about the axis.
TEST(RayTracingLesson, TheLobeDirectionsFollowThePhongDensity) {
  const Vec3 axis = Vec3(1, 2, 3).normalized();
  for (const double q : {1.0, 16.0, 128.0}) {
    double sum = 0;
    const int n = 200;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < 4; ++j) {
        const Vec3 d = phongLobeDirection(axis, q, (i + 0.5) / n, (j + 0.5) / 4);
        EXPECT_NEAR(d.norm(), 1.0, 1e-12);
        sum += d.dot(axis);
      }
    EXPECT_NEAR(sum / (4 * n), (q + 1) / (q + 2), 1e-3) << q;
  }
}

TEST(RayTracingLesson, APixelOutsideTheImageIsAnErrorNamingTheKey) {
  const Lesson lesson = test::shippedLesson("ray-tracing");
  Step step = test::stepWithFigure(lesson, "casting");
  step.parameters.pixelX = step.parameters.imageSize;
  StepRunner runner(test::repoFolders().scenes);
  const std::string message = test::inputErrorOf([&] { runner.run(lesson, step); });
  EXPECT_NE(message.find("outside the image"), std::string::npos) << message;
}

}  // namespace
}  // namespace rt::lesson
