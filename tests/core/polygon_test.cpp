// Geometry of single polygons: the quantities the scene loader's checks rest on.
#include "core/polygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rt {
namespace {

const Polygon kUnitSquare = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};

TEST(Polygon, NewellNormalIsTwiceTheAreaAlongTheRightHandNormal) {
  EXPECT_TRUE(newellNormal(kUnitSquare).isApprox(Vec3(0, 0, 2)));
  const Polygon reversed(kUnitSquare.rbegin(), kUnitSquare.rend());
  EXPECT_TRUE(newellNormal(reversed).isApprox(Vec3(0, 0, -2)));
  // A 3-4-5 right triangle tilted into the plane x + z = 0 keeps its area 6.
  const Polygon triangle = {Vec3(0, 0, 0), Vec3(3, 0, -3) / std::sqrt(2.0), Vec3(0, 4, 0)};
  EXPECT_NEAR(polygonArea(triangle), 6.0, 1e-12);
  EXPECT_TRUE(newellNormal(triangle).normalized().isApprox(Vec3(1, 0, 1).normalized()));
}

TEST(Polygon, CentroidIsAreaWeighted) {
  EXPECT_TRUE(polygonCentroid(kUnitSquare).isApprox(Vec3(0.5, 0.5, 0)));
  // Extra vertices on one edge move the vertex mean but not the area centroid.
  const Polygon square = {Vec3(0, 0, 0), Vec3(0.25, 0, 0), Vec3(0.5, 0, 0),
                          Vec3(1, 0, 0), Vec3(1, 1, 0),    Vec3(0, 1, 0)};
  EXPECT_TRUE(polygonCentroid(square).isApprox(Vec3(0.5, 0.5, 0)));
  const Polygon triangle = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(0, 3, 0)};
  EXPECT_TRUE(polygonCentroid(triangle).isApprox(Vec3(1, 1, 0)));
}

TEST(Polygon, PlanarityOfATwistedQuad) {
  EXPECT_DOUBLE_EQ(planarityDeviation(kUnitSquare), 0.0);
  EXPECT_DOUBLE_EQ(deviationFromFirstPlane(kUnitSquare), 0.0);
  // Lifting one corner by h: it is h from the plane of the other three, and the best-fit plane through the
  // centroid splits the twist evenly, h/4 from every corner.
  const double h = 0.01;
  const Polygon twisted = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, h)};
  EXPECT_NEAR(deviationFromFirstPlane(twisted), h, 1e-6);
  EXPECT_NEAR(planarityDeviation(twisted), h / 4, 1e-6);
  EXPECT_DOUBLE_EQ(deviationFromFirstPlane({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}), 0.0);
}

TEST(Polygon, ConvexityAndTurning) {
  const Vec3 up(0, 0, 1);
  EXPECT_TRUE(isConvex(kUnitSquare, up));
  EXPECT_FALSE(isConvex(kUnitSquare, -up));  // seen from the back it turns clockwise
  EXPECT_NEAR(totalTurning(kUnitSquare, up), 2 * std::numbers::pi, 1e-12);
  const Polygon lShape = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0),
                          Vec3(1, 1, 0), Vec3(1, 2, 0), Vec3(0, 2, 0)};
  EXPECT_FALSE(isConvex(lShape, up));
  // Collinear vertices are allowed.
  EXPECT_TRUE(isConvex({Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, up));
  // A pentagram turns the same way at every vertex but goes around twice.
  Polygon star;
  for (int k = 0; k < 5; ++k) {
    const double a = 2 * std::numbers::pi * (2 * k % 5) / 5;
    star.push_back(Vec3(std::cos(a), std::sin(a), 0));
  }
  EXPECT_TRUE(isConvex(star, up));
  EXPECT_NEAR(totalTurning(star, up), 4 * std::numbers::pi, 1e-9);
  // The normal's length does not matter.
  EXPECT_NEAR(totalTurning(kUnitSquare, 5 * up), 2 * std::numbers::pi, 1e-12);
}

TEST(Polygon, FanTriangulationKeepsWindingAndArea) {
  const Polygon hexagon = {Vec3(2, 0, 0),  Vec3(1, 1.7, 0),   Vec3(-1, 1.7, 0),
                           Vec3(-2, 0, 0), Vec3(-1, -1.7, 0), Vec3(1, -1.7, 0)};
  const std::vector<Polygon> triangles = fanTriangulate(hexagon);
  ASSERT_EQ(triangles.size(), 4u);
  double area = 0;
  for (const Polygon& t : triangles) {
    EXPECT_GT(newellNormal(t).z(), 0);
    area += polygonArea(t);
  }
  EXPECT_NEAR(area, polygonArea(hexagon), 1e-12);
  EXPECT_DOUBLE_EQ(maxEdgeLength(kUnitSquare), 1.0);
}

}  // namespace
}  // namespace rt
