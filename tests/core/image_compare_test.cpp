// The error of an image against a noisy reference: the reference's noise variance is taken out of the mean
// squared difference, so an image that equals the truth scores about zero however noisy the reference.
#include <gtest/gtest.h>

#include <cmath>

#include "core/formfactor/sampling.h"
#include "core/pathtrace/image_compare.h"

namespace rt {
namespace {

TEST(ImageCompare, ExactReferenceGivesTheRelativeError) {
  TracedImage reference{RgbImage(8, 4), RgbImage(8, 4), 0};
  RgbImage image(8, 4);
  for (std::size_t k = 0; k < image.pixels.size(); ++k) {
    reference.B.pixels[k] = Rgb::Constant(2.0);
    image.pixels[k] = Rgb::Constant(k % 2 ? 2.2 : 1.8);  // 10 % off everywhere
  }
  const ImageError e = compareToReference(image, reference);
  EXPECT_NEAR(e.rmsDifference, 0.1, 1e-12);
  EXPECT_NEAR(e.error, 0.1, 1e-12);
  EXPECT_EQ(e.referenceNoise, 0.0);
  EXPECT_NEAR(e.low, 0.1, 1e-12);  // every pixel says the same: no spread
  EXPECT_NEAR(e.high, 0.1, 1e-12);
}

TEST(ImageCompare, TheReferencesNoiseIsTakenOut) {
  const int w = 200, h = 100;
  TracedImage reference{RgbImage(w, h), RgbImage(w, h), 0};
  RgbImage truth(w, h);
  PairRandom random(3, 0, 0);
  for (std::size_t k = 0; k < truth.pixels.size(); ++k) {
    truth.pixels[k] = Rgb::Constant(1.0);
    // Gaussian noise of standard deviation 0.05 (Box-Muller), and the reference says so.
    const double u = random.uniform() + 1e-300, v = random.uniform();
    const double n = std::sqrt(-2 * std::log(u)) * std::cos(2 * M_PI * v);
    reference.B.pixels[k] = Rgb::Constant(1.0 + 0.05 * n);
    reference.error.pixels[k] = Rgb::Constant(0.05);
  }
  const ImageError e = compareToReference(truth, reference);
  EXPECT_NEAR(e.rmsDifference, 0.05, 0.003);
  EXPECT_NEAR(e.referenceNoise, 0.05, 1e-3);
  EXPECT_LT(e.low, 1e-9);  // zero is inside the interval
  EXPECT_LT(e.error, 0.01);
}

}  // namespace
}  // namespace rt
