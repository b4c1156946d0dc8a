// The thin lens of the ray tracer's depth of field: every ray of a pixel passes through the one point of the
// plane of focus, starts on the lens's disc, and a point off that plane is spread over the disc of equation
// (blur-disc) of the ray-tracing lesson.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/pathtrace/path_tracer.h"
#include "core/raytrace/thin_lens.h"

namespace rt {
namespace {

const Camera kCamera{{0, 0, 0}, {0, 0, 10}, {0, 1, 0}, 40};

TEST(ThinLens, EveryRayOfAPixelMeetsThePlaneOfFocusAtOnePoint) {
  const ThinLens lens{2.0, 8.0};
  const Vec3 pinhole = cameraRay(kCamera, 64, 64, 20.5, 40.5);
  const Vec3 focus = (8.0 / pinhole.z()) * pinhole;
  for (const double u : {0.0, 0.3, 0.99})
    for (const double v : {0.1, 0.5, 0.8}) {
      const LensRay ray = thinLensRay(kCamera, lens, pinhole, u, v);
      EXPECT_NEAR(ray.origin.z(), 0.0, 1e-12) << "on the lens";
      EXPECT_LE(ray.origin.norm(), 2.0 + 1e-12);
      EXPECT_NEAR(ray.direction.norm(), 1.0, 1e-12);
      const Vec3 reached = ray.origin + ((8.0 - ray.origin.z()) / ray.direction.z()) * ray.direction;
      EXPECT_NEAR((reached - focus).norm(), 0.0, 1e-9);
    }
}

TEST(ThinLens, APinholeIsTheCameraRayAndZeroFocusIsTheTarget) {
  const Vec3 pinhole = cameraRay(kCamera, 64, 64, 3.5, 7.5);
  const LensRay ray = thinLensRay(kCamera, ThinLens{}, pinhole, 0.7, 0.2);
  EXPECT_EQ(ray.origin, kCamera.position);
  EXPECT_EQ(ray.direction, pinhole);
  EXPECT_DOUBLE_EQ(focusDistanceOf(kCamera, ThinLens{1, 0}), 10.0);
  EXPECT_DOUBLE_EQ(focusDistanceOf(kCamera, ThinLens{1, 4}), 4.0);
}

// The blur disc of a point at depth z: the spread of the pixels whose rays pass through it, measured by
// tracing the lens's rim, against 2 a |1/f - 1/z| over the angle of one pixel.
TEST(ThinLens, TheBlurDiscFollowsTheFormula) {
  const ThinLens lens{0.5, 8.0};
  const int height = 256;
  for (const double z : {4.0, 8.0, 20.0}) {
    const double expected =
        2 * 0.5 * std::abs(1 / 8.0 - 1 / z) / (2 * std::tan(20.0 * std::numbers::pi / 180.0) / height);
    EXPECT_NEAR(blurDiscPixels(kCamera, lens, height, z), expected, 1e-9 * (1 + expected));
    // A point on the axis at depth z, seen from the lens's rim at (a, 0, 0), is reached through the focus
    // point Q = L + (P - L) f / z: the disc's radius on the plane of focus is a |1 - f/z|.
    const Vec3 L(0.5, 0, 0), P(0, 0, z);
    const Vec3 Q = L + (P - L) * (8.0 / z);
    const double angle = 2 * std::abs(Q.x()) / 8.0;
    EXPECT_NEAR(angle / (2 * std::tan(20.0 * std::numbers::pi / 180.0) / height), expected,
                1e-9 * (1 + expected));
  }
  EXPECT_EQ(blurDiscPixels(kCamera, ThinLens{}, height, 20), 0.0) << "a pinhole blurs nothing";
}

}  // namespace
}  // namespace rt
