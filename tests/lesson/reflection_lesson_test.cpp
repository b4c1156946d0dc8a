// The lesson on reflection: what its text says about the numbers of its reflection steps, checked on those
// steps (same parameters), and what the stage does when a reader changes the BRDF.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "core/io/rgb_image.h"
#include "lesson/lesson_parser.h"
#include "lesson/step_runner.h"
#include "lesson_test_support.h"

namespace rt::lesson {
namespace {

constexpr double kPi = std::numbers::pi;

using Ran = test::RanStep;

// Runs the step of `lesson` that draws `figure`, with `change` applied to its parameters first.
Ran run(const std::string& figure, const std::function<void(StepParameters&)>& change = {},
        const std::string& lesson = "reflection") {
  return test::runStepWithFigure(lesson, figure, change);
}

TEST(ReflectionLesson, IsTheThirdLesson) {
  EXPECT_EQ(test::shippedLesson("reflection").order, 3);
}

TEST(ReflectionLesson, PhongIsReciprocalAndReflectsAllOfKdPlusKsAlongTheNormal) {
  const Ran r = run("albedo");
  EXPECT_LT(r["reciprocity-error"], 1e-12);
  EXPECT_NEAR(r["kd"] + r["ks"], r["reflectance"], 1e-12);
  EXPECT_NEAR(r["albedo.normal"], r["reflectance"], 1e-3);
  EXPECT_LT(r["albedo"], r["albedo.normal"]) << "less from the step's incidence";
  EXPECT_LT(r["albedo.grazing"], r["albedo"]) << "less still at grazing incidence";
  EXPECT_LE(r["albedo.max"], r["reflectance"] + 1e-3);
}

TEST(ReflectionLesson, EveryModelStaysBelowItsReflectance) {
  for (const char* model : {"lambertian", "mirror", "phong", "ward"})
    for (double q : {1.0, 128.0}) {
      const Ran r = run("albedo", [&](StepParameters& p) {
        p.brdfModel = model;
        p.phongExponent = q;
        p.specularFraction = 1;
        p.anisotropy = 8;
      });
      EXPECT_LE(r["albedo.max"], r["reflectance"] + 2e-3) << model << " q = " << q;
      EXPECT_LT(r["reciprocity-error"], 1e-12) << model;
    }
}

TEST(ReflectionLesson, TheLambertianLobeIsASphereWhateverTheIncidence) {
  const Ran r = run("lambertian");
  EXPECT_NEAR(r["f.diffuse"], r["reflectance"] / kPi, 1e-12);
  EXPECT_NEAR(r["lambert.albedo"], r["reflectance"], 1e-5);
  EXPECT_NEAR(r["albedo"], r["reflectance"], 1e-5);
  EXPECT_NEAR(r["lobe.peak"], r["f.diffuse"], 1e-3 * r["f.diffuse"]) << "peak f cos(theta) along the normal";
  const Ran turned = run("lambertian", [](StepParameters& p) { p.incidenceAngle = 75; });
  EXPECT_DOUBLE_EQ(turned["lobe.peak"], r["lobe.peak"]);
  ASSERT_TRUE(r.result.reflection);
  EXPECT_GT(r.result.mesh.size(), 100u) << "the app's 3D view has the lobe to show";
}

TEST(ReflectionLesson, TheMirrorIsADeltaItsAlbedoItsWeight) {
  const Ran r = run("mirror");
  EXPECT_DOUBLE_EQ(r["delta"], r["reflectance"]);
  EXPECT_DOUBLE_EQ(r["albedo"], r["reflectance"]);
  EXPECT_EQ(r["f.peak"], 0.0) << "no finite value in the mirror direction";
}

TEST(ReflectionLesson, PhongsNormalisationAndPeak) {
  const Ran r = run("phong");
  EXPECT_NEAR(r["phong-normalisation"], (r["q"] + 2) / (2 * kPi), 1e-12);
  EXPECT_NEAR(r["kd"], r["ks"], 1e-12) << "specular fraction 0.5";
  EXPECT_NEAR(r["f.peak"], r["f.diffuse"] + r["ks"] * r["phong-normalisation"], 1e-12);
  EXPECT_GT(r["f.peak"], 5 * r["f.diffuse"]);
  EXPECT_NEAR(r["albedo.max"], r["albedo.normal"], 1e-3) << "never more than at the normal";
}

TEST(ReflectionLesson, TheExponentSweepNarrowsTheHighlight) {
  const Ran one = run("phong-sweep", [](StepParameters& p) { p.phongExponent = 1; });
  EXPECT_NEAR(one["half-width"], 60.0, 1e-9);
  const Ran sharp = run("phong-sweep", [](StepParameters& p) { p.phongExponent = 128; });
  EXPECT_LT(sharp["half-width"], 10.0) << "within a few degrees";
  EXPECT_GT(sharp["phong-normalisation"], one["phong-normalisation"]) << "a smaller and brighter peak";
  const Ran r = run("phong-sweep");
  EXPECT_NEAR(r["half-width"], std::acos(std::pow(0.5, 1 / r["q"])) * 180 / kPi, 1e-9);
  ASSERT_TRUE(r.result.reflection);
  EXPECT_EQ(r.result.reflection->exponents.front(), 1.0);
  EXPECT_EQ(r.result.reflection->exponents.back(), 128.0);
}

TEST(ReflectionLesson, WardsAnisotropyIsTheRatioOfItsSpreads) {
  const Ran r = run("anisotropic");
  EXPECT_NEAR(r["alpha-x"] / r["alpha-y"], 4.0, 1e-12);
  EXPECT_NEAR(r["alpha-x"] * r["alpha-y"], 2 / (r["q"] + 2), 1e-12);
  EXPECT_LT(r["albedo.max"], r["reflectance"]);
  const Ran round = run("anisotropic", [](StepParameters& p) { p.anisotropy = 1; });
  EXPECT_DOUBLE_EQ(round["alpha-x"], round["alpha-y"]);
}

TEST(ReflectionLesson, TheWorkedExampleAddsUp) {
  const Ran r = run("example");
  EXPECT_NEAR(r["example.alpha"], std::abs(r["view"] - r["incidence"]), 1e-9);
  EXPECT_NEAR(r["example.f"], r["f.diffuse"] + r["example.f-specular"], 1e-12);
  EXPECT_NEAR(r["example.f-specular"], r["ks"] * r["phong-normalisation"] * r["example.cos-alpha-q"], 1e-12);
  EXPECT_NEAR(r["example.L"], r["example.f"] * r["example.H"], 1e-9);
  EXPECT_NEAR(r["example.L"], r["example.L-diffuse"] + r["example.L-specular"], 1e-9);
  EXPECT_NEAR(r["example.L-lambert"], r["reflectance"] * r["example.H"] / kPi, 1e-9);
  // The viewer in the mirror direction sees the peak.
  const double view = r["view"];
  const Ran mirror = run("example", [view](StepParameters& p) { p.incidenceAngle = view; });
  EXPECT_NEAR(mirror["example.f"], mirror["f.peak"], 1e-12);
}

TEST(ReflectionLesson, NoAmbientConstantMakesTheLocalPictureTheRadiosityOne) {
  const Ran r = run("phong-local");
  ASSERT_TRUE(r.result.reflection);
  const ReflectionData& d = *r.result.reflection;
  ASSERT_EQ(d.local.pixels.size(), d.radiosity.pixels.size());
  EXPECT_GT(r["image.local.mean"], 0);
  EXPECT_GT(r["image.radiosity.mean"], 0);
  // The classic ambient estimate is the one of the local-vs-global lesson (same scene, mesh and method).
  const Ran classic = run("local-global", {}, "local-vs-global");
  EXPECT_NEAR(r["ambient"], classic["ambient"], 1e-9);
  for (double ambient : {0.01, 0.6, 2.0}) {
    const Ran a = run("phong-local", [ambient](StepParameters& p) { p.ambientLight = ambient; });
    const ReflectionData& e = *a.result.reflection;
    EXPECT_GT(rmsDifference(e.local, e.radiosity), 0.1 * a["image.radiosity.mean"]) << ambient;
  }
}

TEST(ReflectionLesson, MoreAmbientBrightensTheLocalPictureOnly) {
  const Ran low = run("phong-local", [](StepParameters& p) { p.ambientLight = 0.1; });
  const Ran high = run("phong-local", [](StepParameters& p) { p.ambientLight = 1.0; });
  EXPECT_GT(high["image.local.mean"], low["image.local.mean"]);
  EXPECT_DOUBLE_EQ(high["image.radiosity.mean"], low["image.radiosity.mean"]);
}

// The ambient term is a constant added to the local picture: a reader's new ambient light reuses the rest of
// the picture (and the radiosity one) instead of tracing it again, and the picture is the one a fresh run
// gives.
TEST(ReflectionLesson, ANewAmbientLightDoesNotTraceThePicturesAgain) {
  const Lesson lesson = test::shippedLesson("reflection");
  Step step = test::stepWithFigure(lesson, "phong-local");
  StepRunner runner(test::repoFolders().scenes);
  step.parameters.ambientLight = 0.1;
  const StepResult low = runner.run(lesson, step);
  step.parameters.ambientLight = 1.0;
  const StepResult high = runner.run(lesson, step);
  ASSERT_TRUE(low.reflection && high.reflection);
  ASSERT_NE(high.reflection->lit, nullptr);
  EXPECT_EQ(high.reflection->lit, low.reflection->lit) << "rendered again for an ambient change";
  const StepResult fresh = StepRunner(test::repoFolders().scenes).run(lesson, step);
  EXPECT_NE(fresh.reflection->lit, high.reflection->lit);
  EXPECT_EQ(rmsDifference(fresh.reflection->local, high.reflection->local), 0.0);
  EXPECT_EQ(rmsDifference(fresh.reflection->radiosity, high.reflection->radiosity), 0.0);
  EXPECT_EQ(fresh.values.at("image.local.mean"), high.values.at("image.local.mean"));
  EXPECT_GT(rmsDifference(low.reflection->local, high.reflection->local), 0.0);
  // What the pictures depend on renders them again.
  step.parameters.phongExponent = 40;
  const StepResult sharper = runner.run(lesson, step);
  EXPECT_NE(sharper.reflection->lit, high.reflection->lit);
}

}  // namespace
}  // namespace rt::lesson
