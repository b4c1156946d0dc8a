// Solid angles of polygons seen from a point and the hemisphere's projected solid angle: closed forms, the
// whole sphere, and where the small-patch approximation holds.
#include "core/radiometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rt {
namespace {

constexpr double kPi = std::numbers::pi;

// An a x b rectangle centred on the z axis at height h, facing down (towards the origin).
Polygon rectangleAbove(double a, double b, double h) {
  return {Vec3(-a / 2, -b / 2, h), Vec3(-a / 2, b / 2, h), Vec3(a / 2, b / 2, h), Vec3(a / 2, -b / 2, h)};
}

// The six faces of the cube [-1, 1]^3, each counter-clockwise seen from outside.
std::vector<Polygon> cubeFaces() {
  std::vector<Polygon> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Polygon face;
      for (const auto& [a, b] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
        Vec3 p;
        p[axis] = side;
        p[u] = a;
        p[v] = side > 0 ? b : -b;
        face.push_back(p);
      }
      faces.push_back(face);
    }
  return faces;
}

TEST(Radiometry, TheSolidAngleOfACentredRectangleHasItsClosedForm) {
  // Omega = 4 arcsin(a b / sqrt((a^2 + 4 h^2)(b^2 + 4 h^2))).
  for (const auto& [a, b, h] :
       {std::tuple{2.0, 2.0, 1.0}, {0.5, 0.3, 1.0}, {3.0, 1.0, 0.2}, {0.1, 0.1, 10.0}}) {
    const double expected = 4 * std::asin(a * b / std::sqrt((a * a + 4 * h * h) * (b * b + 4 * h * h)));
    EXPECT_NEAR(polygonSolidAngle(Vec3::Zero(), rectangleAbove(a, b, h)), expected, 1e-12 * (1 + expected));
  }
  // A cube's face seen from its centre: a sixth of the sphere.
  EXPECT_NEAR(polygonSolidAngle(Vec3::Zero(), rectangleAbove(2, 2, 1)), 4 * kPi / 6, 1e-12);
}

TEST(Radiometry, TheFacesOfACubeFillTheSphereFromAnyInnerPoint) {
  for (const Vec3& point : {Vec3(0, 0, 0), Vec3(0.3, -0.7, 0.9), Vec3(-0.99, 0.5, 0.1)}) {
    double sum = 0;
    for (const Polygon& face : cubeFaces()) sum += polygonSolidAngle(point, face);
    EXPECT_NEAR(sum, 4 * kPi, 1e-10) << point.transpose();
  }
}

TEST(Radiometry, TheWindingAndTheSideDoNotChangeTheSolidAngle) {
  const Polygon p = rectangleAbove(0.7, 0.4, 0.9);
  const Polygon reversed(p.rbegin(), p.rend());
  EXPECT_DOUBLE_EQ(polygonSolidAngle(Vec3::Zero(), p), polygonSolidAngle(Vec3::Zero(), reversed));
  EXPECT_NEAR(polygonSolidAngle(Vec3::Zero(), p), polygonSolidAngle(Vec3(0, 0, 1.8), p), 1e-12);
  EXPECT_EQ(polygonSolidAngle(Vec3(5, 5, 0.9), p), 0.0);  // in the polygon's plane
}

TEST(Radiometry, TheSmallPatchApproximationHoldsFarAwayAndOverestimatesNear) {
  for (double h : {0.5, 1.0, 4.0, 100.0}) {
    const Polygon p = rectangleAbove(1, 1, h);
    const double exact = polygonSolidAngle(Vec3::Zero(), p), approx = smallPatchSolidAngle(Vec3::Zero(), p);
    EXPECT_DOUBLE_EQ(approx, 1.0 / (h * h));
    EXPECT_GT(approx, exact) << h;  // every other point of the patch is farther and more oblique
    if (h >= 100) {
      EXPECT_NEAR(approx / exact, 1.0, 1e-4);
    }
  }
  // Tilted by 60 degrees about the x axis: the cosine halves it.
  const double t = kPi / 3;
  const Polygon tilted{Vec3(-0.005, -0.005 * std::cos(t), 10 - 0.005 * std::sin(t)),
                       Vec3(0.005, -0.005 * std::cos(t), 10 - 0.005 * std::sin(t)),
                       Vec3(0.005, 0.005 * std::cos(t), 10 + 0.005 * std::sin(t)),
                       Vec3(-0.005, 0.005 * std::cos(t), 10 + 0.005 * std::sin(t))};
  EXPECT_NEAR(smallPatchSolidAngle(Vec3::Zero(), tilted), 1e-4 * 0.5 / 100, 1e-15);
  EXPECT_NEAR(polygonSolidAngle(Vec3::Zero(), tilted) / smallPatchSolidAngle(Vec3::Zero(), tilted), 1, 1e-5);
}

TEST(Radiometry, TheHemisphereIntegralOfTheCosineIsPi) {
  EXPECT_NEAR(hemisphereCosineIntegral(1000), kPi, 1e-5);
  // The midpoint rule: the error falls fourfold when the rings double.
  const double e100 = std::abs(hemisphereCosineIntegral(100) - kPi);
  const double e200 = std::abs(hemisphereCosineIntegral(200) - kPi);
  EXPECT_NEAR(e100 / e200, 4.0, 0.05);
  EXPECT_EQ(hemisphereCosineIntegral(0), 0.0);
}

}  // namespace
}  // namespace rt
