// The convex polygon type (core/geometry/convex_polygon.h): its measures on both buffers, the growing one
// keeping every corner past its inline room, and the fixed one refusing more corners than it holds.
#include "core/geometry/convex_polygon.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/check.h"
#include "core/polygon.h"

namespace rt {
namespace {

TEST(GeometryConvexPolygon, MeasuresOfAUnitSquareAgreeOnBothBuffers) {
  const ConvexPolygon grows{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  const FixedConvexPolygon<4> fixed{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  for (double area : {grows.area(), fixed.area()}) EXPECT_DOUBLE_EQ(area, 1.0);
  EXPECT_EQ(grows.centre(), Vec3(0.5, 0.5, 0));
  EXPECT_EQ(fixed.centre(), Vec3(0.5, 0.5, 0));
  EXPECT_DOUBLE_EQ(fixed.radius(), std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(grows.longestEdge(), 1.0);
  // Counter-clockwise about +z: Newell's vector points up, twice the area long.
  EXPECT_EQ(twiceAreaVector(grows.data(), grows.count), Vec3(0, 0, 2));
  EXPECT_EQ(newellNormal(grows.toPolygon()), Vec3(0, 0, 2));
}

TEST(GeometryConvexPolygon, NoCornersHaveTheOriginAsCentre) {
  const ConvexPolygon empty;
  EXPECT_EQ(empty.centre(), Vec3::Zero());
  EXPECT_EQ(empty.area(), 0.0);
}

// A polygon of more corners than its inline room keeps them all (on the heap), and so do its copies.
TEST(GeometryConvexPolygon, TheGrowingBufferKeepsEveryCorner) {
  constexpr int kCorners = 3 * ConvexPolygon::kInline;
  Polygon disc;
  for (int k = 0; k < kCorners; ++k) {
    const double angle = 2 * M_PI * k / kCorners;
    disc.emplace_back(std::cos(angle), std::sin(angle), 0);
  }
  ConvexPolygon many;
  many.assign(disc.data(), kCorners);
  const ConvexPolygon copy = many;
  ConvexPolygon assigned;
  assigned.assign(many);
  for (const ConvexPolygon* p : std::initializer_list<const ConvexPolygon*>{&many, &copy, &assigned}) {
    ASSERT_EQ(p->count, kCorners);
    EXPECT_EQ(p->toPolygon(), disc);
    EXPECT_NEAR(p->area(), polygonArea(disc), 1e-15);
  }
}

// A fixed polygon asked for more corners than it holds fails loudly, in every build (not only with the
// RT_CHECKs on): a silent loss of corners would be a wrong form factor.
TEST(GeometryConvexPolygon, TheFixedBufferRefusesMoreCornersThanItHolds) {
  FixedConvexPolygon<4> panel;
  EXPECT_NO_THROW(panel.reserve(4));
  EXPECT_THROW(panel.reserve(5), CheckFailure);
  EXPECT_THROW(
      (FixedConvexPolygon<4>{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0.5, 2, 0), Vec3(0, 1, 0)}),
      CheckFailure);
}

}  // namespace
}  // namespace rt
