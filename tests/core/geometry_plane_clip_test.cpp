// Cutting a convex polygon by a plane (core/geometry/plane_clip.h): each convention of the header, for each
// way in (the shadow clipper's split and front clip with a margin, the exact reference's clip with none,
// the contact lines' cut), and the one place where two conventions differ on purpose.
#include "core/geometry/plane_clip.h"

#include <gtest/gtest.h>

#include <vector>

namespace rt {
namespace {

const Polygon kSquare{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const Vec3 kAlongX{1, 0, 0};

ConvexPolygon square() {
  ConvexPolygon p;
  p.assign(kSquare.data(), 4);
  return p;
}

// Corners on the plane belong to both parts, once; a crossing is added to both.
TEST(GeometryPlaneClip, ACornerOnThePlaneGoesToBothPartsOnce) {
  // The diagonal x = y through corners 0 and 2: each part is a triangle of those two and one more.
  ConvexPolygon front, back;
  const int side = splitByPlane(square(), Vec3(0, 0, 0), Vec3(1, -1, 0), 0.0, front, &back);
  ASSERT_EQ(side, 0);
  EXPECT_EQ(front.toPolygon(), (Polygon{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}));
  EXPECT_EQ(back.toPolygon(), (Polygon{{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
  // Across the middle: two crossings, each in both parts.
  ASSERT_EQ(splitByPlane(square(), Vec3(0.5, 0, 0), kAlongX, 0.0, front, &back), 0);
  EXPECT_EQ(front.toPolygon(), (Polygon{{0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 1, 0}}));
  EXPECT_EQ(back.toPolygon(), (Polygon{{0, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0}, {0, 1, 0}}));
  EXPECT_DOUBLE_EQ(front.area() + back.area(), 1.0);
}

// The margin: corners within it count as on the plane, so a plane that only grazes a corner cuts nothing.
TEST(GeometryPlaneClip, CornersWithinTheMarginCountAsOnThePlane) {
  ConvexPolygon front, back;
  const double eps = 1e-9;
  // x = 1e-12 grazes the corners at x = 0: all of the square is in front.
  EXPECT_EQ(splitByPlane(square(), Vec3(1e-12, 0, 0), kAlongX, eps * eps, front, &back), 1);
  EXPECT_EQ(splitByPlane(square(), Vec3(1 - 1e-12, 0, 0), kAlongX, eps * eps, front, &back), -1);
  // With no margin the same plane cuts a sliver off.
  EXPECT_EQ(splitByPlane(square(), Vec3(1e-12, 0, 0), kAlongX, 0.0, front, &back), 0);
  EXPECT_NEAR(back.area(), 1e-12, 1e-16);  // (Newell's sum at coordinates of 1: rounding of 1e-16)
}

// clipToFront(): eps in lengths, whatever the normal's length; whole when nothing is behind, empty when
// nothing is in front, a polygon wholly on the plane dropped.
TEST(GeometryPlaneClip, ClipToFrontDropsAPolygonOnThePlane) {
  ConvexPolygon out;
  EXPECT_TRUE(clipToFront(kSquare.data(), 4, Vec3(-1e-12, 0, 0), 1000 * kAlongX, 1e-9, out));
  EXPECT_EQ(out.count, 4);
  EXPECT_FALSE(clipToFront(kSquare.data(), 4, Vec3(0.5, 0, 0), kAlongX, 1e-9, out));
  EXPECT_DOUBLE_EQ(out.area(), 0.5);
  EXPECT_FALSE(clipToFront(kSquare.data(), 4, Vec3(0, 0, 0), Vec3(0, 0, 1), 1e-9, out));  // in the plane
  EXPECT_EQ(out.count, 0);
  EXPECT_FALSE(clipToFront(kSquare.data(), 4, Vec3(0, 0, 0), Vec3::Zero(), 1e-9, out));  // no direction
  EXPECT_EQ(out.count, 0);
}

// clipToHalfspace(): no tolerance, and a polygon with nothing behind kept whole even in the plane.
TEST(GeometryPlaneClip, ClipToHalfspaceKeepsAPolygonOnThePlane) {
  EXPECT_EQ(clipToHalfspace(kSquare, Vec3(0, 0, 0), Vec3(0, 0, 1)), kSquare);
  EXPECT_EQ(clipToHalfspace(kSquare, Vec3(0, 0, 0), Vec3(0, 0, -1)), kSquare);
  EXPECT_TRUE(clipToHalfspace(kSquare, Vec3(1, 0, 0), kAlongX).empty());  // an edge is left: no area
  const Polygon half = clipToHalfspace(kSquare, Vec3(1e-12, 0, 0), kAlongX);
  ASSERT_EQ(half.size(), 4u);
  EXPECT_EQ(half[0], Vec3(1e-12, 0, 0));
}

// The contact lines' cut repeats a corner on the plane next to one behind (plane_clip.h says why it stays):
// the same cut by the common convention has it once.
TEST(GeometryPlaneClip, TheContactCutRepeatsACornerOnThePlane) {
  const Polygon triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  // x >= 0 through corners 0 and 2, corner 1 in front: nothing behind, both keep the triangle.
  EXPECT_EQ(clipToHalfspaceTwiceOnPlane(triangle, Vec3(0, 0, 0), kAlongX), triangle);
  // x <= 0: corners 0 and 2 on the plane, corner 1 behind. Common: the edge 0-2, no area, empty. Contact
  // cut: each corner on the plane twice, itself and the crossing of its edge to corner 1; four corners of
  // no area, which its caller keeps as a piece by their count.
  EXPECT_TRUE(clipToHalfspace(triangle, Vec3(0, 0, 0), -kAlongX).empty());
  const Polygon repeated = clipToHalfspaceTwiceOnPlane(triangle, Vec3(0, 0, 0), -kAlongX);
  EXPECT_EQ(repeated, (Polygon{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 1, 0}}));
}

// The 2D cells of the mesher cut by the same routine: heights from a line, both parts.
TEST(GeometryPlaneClip, TwoDimensionalCornersCutTheSameWay) {
  const std::vector<Vec2> cell{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  const double heights[] = {-1, 1, 1, -1};  // x - 1
  std::vector<Vec2> left, right;
  cutByHeights(
      cell.data(), heights, 4, [&](const Vec2& p) { left.push_back(p); },
      [&](const Vec2& p) { right.push_back(p); });
  EXPECT_EQ(left, (std::vector<Vec2>{{1, 0}, {2, 0}, {2, 2}, {1, 2}}));
  EXPECT_EQ(right, (std::vector<Vec2>{{0, 0}, {1, 0}, {1, 2}, {0, 2}}));
}

}  // namespace
}  // namespace rt
