// The four BRDF models against the two properties of every physical BRDF (reciprocity, albedo at most 1)
// over many directions, and against closed forms: the Lambertian albedo is rho at every incidence, and
// Phong's normalised lobe reflects exactly k_s of light arriving along the normal, since the integral of
// cos^q(theta) cos(theta) over the hemisphere is 2 pi / (q + 2).
#include "core/brdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/brdf_integrals.h"

namespace rt {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Brdf> everyModel() {
  std::vector<Brdf> models;
  for (BrdfModel m : {BrdfModel::Lambertian, BrdfModel::Mirror, BrdfModel::Phong, BrdfModel::Ward})
    for (double q : {1.0, 8.0, 128.0})
      for (double anisotropy : {1.0, 4.0}) models.push_back(makeBrdf(m, 0.95, 0.5, q, anisotropy));
  return models;
}

TEST(Brdf, NamesRoundTrip) {
  for (const auto& name : brdfModelNames()) {
    const auto model = brdfModelFromName(name);
    ASSERT_TRUE(model.has_value()) << name;
    EXPECT_EQ(brdfModelName(*model), name);
  }
  EXPECT_FALSE(brdfModelFromName("blinn").has_value());
}

TEST(Brdf, EveryModelIsReciprocal) {
  for (const Brdf& b : everyModel())
    EXPECT_LT(reciprocityError(b, 20000, 7), 1e-12) << brdfModelName(b.model) << " q = " << b.exponent;
}

TEST(Brdf, NoModelReflectsMoreThanArrives) {
  for (const Brdf& b : everyModel()) {
    const double largest = largestAlbedo(b, 128, 256);
    // k_d + k_s = 0.95: the albedo stays below it, up to the midpoint rule's error.
    EXPECT_LE(largest, 0.95 + 2e-3) << brdfModelName(b.model) << " q = " << b.exponent;
    EXPECT_GT(largest, 0.5) << brdfModelName(b.model);
  }
}

TEST(Brdf, WardAtTheLimitOfItsSpreadStillConservesEnergy) {
  // The widest lobe the lessons offer (q = 0, alpha = 1) stretched 16 to 1, all of it specular.
  Brdf b = makeBrdf(BrdfModel::Ward, 1.0, 1.0, 0.0, 16.0);
  EXPECT_LE(largestAlbedo(b, 256, 512), 1.0 + 2e-3);
}

TEST(Brdf, LambertianAlbedoIsRhoAtEveryIncidence) {
  const Brdf b = makeBrdf(BrdfModel::Lambertian, 0.7, 0.3, 10, 1);
  EXPECT_DOUBLE_EQ(b.diffuse, 0.7);
  EXPECT_DOUBLE_EQ(evaluateBrdf(b, directionAt(0.3, 1), directionAt(1.2, 4)), 0.7 / kPi);
  for (double degrees : {0.0, 30.0, 60.0, 89.0})
    EXPECT_NEAR(directionalAlbedo(b, directionAt(degrees * kPi / 180, 0.4)), 0.7, 1e-5) << degrees;
}

TEST(Brdf, PhongNormalisationMatchesTheClosedForm) {
  for (double q : {1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0}) {
    EXPECT_DOUBLE_EQ(phongNormalisation(q), (q + 2) / (2 * kPi));
    // All specular: along the normal the lobe reflects exactly k_s.
    const Brdf b = makeBrdf(BrdfModel::Phong, 0.6, 1.0, q, 1);
    EXPECT_NEAR(directionalAlbedo(b, Vec3(0, 0, 1), 1024, 8), 0.6, 1e-4) << q;
    // Off the normal part of the lobe falls below the horizon: less.
    EXPECT_LT(directionalAlbedo(b, directionAt(1.2, 0)), 0.6) << q;
  }
}

TEST(Brdf, PhongPeaksInTheMirrorDirection) {
  const Brdf b = makeBrdf(BrdfModel::Phong, 0.8, 0.5, 32, 1);
  const Vec3 wi = directionAt(0.7, 0.2);
  const double peak = evaluateBrdf(b, wi, mirrorDirection(wi));
  EXPECT_NEAR(peak, 0.4 / kPi + 0.4 * phongNormalisation(32), 1e-12);
  EXPECT_LT(evaluateBrdf(b, wi, directionAt(0.8, 0.2 + kPi)), peak);
}

TEST(Brdf, TheMirrorIsADelta) {
  const Brdf b = makeBrdf(BrdfModel::Mirror, 0.9, 0.2, 8, 1);
  const Vec3 wi = directionAt(0.5, 1.0);
  EXPECT_EQ(evaluateBrdf(b, wi, mirrorDirection(wi)), 0.0) << "no finite value in any direction";
  EXPECT_DOUBLE_EQ(deltaReflectance(b, wi), 0.9);
  EXPECT_DOUBLE_EQ(directionalAlbedo(b, wi), 0.9);
  EXPECT_EQ(deltaReflectance(makeBrdf(BrdfModel::Phong, 0.9, 1, 8, 1), wi), 0.0);
}

TEST(Brdf, WardAnisotropyStretchesTheLobeAlongX) {
  const Brdf b = makeBrdf(BrdfModel::Ward, 0.8, 1.0, 20, 4);
  EXPECT_NEAR(b.alphaX * b.alphaY, 2.0 / 22.0, 1e-12);
  EXPECT_NEAR(b.alphaX / b.alphaY, 4.0, 1e-12);
  const Vec3 wi(0, 0, 1);
  // The same tilt away from the mirror direction costs less along x than along y.
  EXPECT_GT(evaluateBrdf(b, wi, directionAt(0.2, 0)), evaluateBrdf(b, wi, directionAt(0.2, 0.5 * kPi)));
}

TEST(Brdf, BelowTheSurfaceNothingIsReflected) {
  for (const Brdf& b : everyModel()) {
    EXPECT_EQ(evaluateBrdf(b, Vec3(0, 0.6, -0.8), Vec3(0, 0, 1)), 0.0);
    EXPECT_EQ(evaluateBrdf(b, Vec3(0, 0, 1), Vec3(0.6, 0, -0.8)), 0.0);
  }
}

}  // namespace
}  // namespace rt
