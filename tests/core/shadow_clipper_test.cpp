// ShadowClipper's proof that a receiver is wholly hidden (hidesAll), by one face or by a block whose faces
// share the segments between them, against its per-point clipping: where hidesAll says yes, every point of
// the source sees nothing of the receiver; where the shadow is partial it says no.
#include "core/formfactor/quadrature/shadow_clipper.h"

#include "core/box_solid.h"
#include "core/formfactor/quadrature/closed_solids.h"
#include "core/formfactor/quadrature/solid_silhouette.h"

#include <gtest/gtest.h>

#include <vector>

namespace rt {
namespace {

const ConvexPolygon kSource = polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});  // faces +z
const Vec3 kUp{0, 0, 1}, kDown{0, 0, -1};

void expectEveryPointHidden(const ShadowClipper& clipper) {
  for (double s : {0.0, 0.3, 1.0})
    for (double t : {0.0, 0.6, 1.0}) {
      const Vec3 x{s, t, 0};
      bool wholly = false;
      EXPECT_NEAR(clipper.hidden(x, clipper.occluders(), &wholly), clipper.unoccluded(x), 1e-12);
      EXPECT_TRUE(wholly) << s << ", " << t;
    }
}

TEST(ShadowClipper, AWideFaceBetweenParallelSquaresHidesAll) {
  const ConvexPolygon receiver = polygon({{0, 0, 2}, {0, 1, 2}, {1, 1, 2}, {1, 0, 2}});  // faces -z
  const std::vector<Vec3> plate{{-1, -1, 1}, {-1, 2, 1}, {2, 2, 1}, {2, -1, 1}};         // faces -z
  const std::vector<SolidPlanes> none;
  const ShadowClipper clipper(kSource, kUp, receiver, kDown, {{&plate, -1}}, none);
  ASSERT_EQ(clipper.occluders().size(), 1u);
  EXPECT_TRUE(clipper.hidesAll(kSource.v.data(), kSource.count, clipper.occluders()));
  expectEveryPointHidden(clipper);
}

TEST(ShadowClipper, ASmallFaceHidesOnlyPart) {
  const ConvexPolygon receiver = polygon({{0, 0, 2}, {0, 1, 2}, {1, 1, 2}, {1, 0, 2}});
  const std::vector<Vec3> plate{{0.4, 0.4, 1}, {0.4, 0.6, 1}, {0.6, 0.6, 1}, {0.6, 0.4, 1}};
  const std::vector<SolidPlanes> none;
  const ShadowClipper clipper(kSource, kUp, receiver, kDown, {{&plate, -1}}, none);
  EXPECT_FALSE(clipper.hidesAll(kSource.v.data(), kSource.count, clipper.occluders()));
  const Vec3 centre{0.5, 0.5, 0};
  bool wholly = true;
  const double hidden = clipper.hidden(centre, clipper.occluders(), &wholly);
  EXPECT_FALSE(wholly);
  EXPECT_GT(hidden, 0.0);
  EXPECT_LT(hidden, clipper.unoccluded(centre));
}

// From the floor square to a ceiling square off to the side, the segments enter a block through its bottom
// or its near side and leave through its far side or its top: no one face meets them all, the block does.
TEST(ShadowClipper, ABlockHidesAllWhereNoOneOfItsFacesDoes) {
  const ConvexPolygon receiver = polygon({{3, 0, 3}, {3, 1, 3}, {4, 1, 3}, {4, 0, 3}});  // faces -z
  const Box block = box({1.2, -1, 0.5}, {2.8, 2, 2.5});
  std::vector<OccluderPolygon> faces;
  for (const auto& face : block.faces) faces.push_back({&face, 0});
  const std::vector<SolidPlanes> solids{block.planes};
  const std::vector<Vec3> centres{block.centre};

  const ShadowClipper withoutCentres(kSource, kUp, receiver, kDown, faces, solids);
  EXPECT_FALSE(withoutCentres.hidesAll(kSource.v.data(), kSource.count, withoutCentres.occluders()));
  const ShadowClipper clipper(kSource, kUp, receiver, kDown, faces, solids, &centres);
  EXPECT_TRUE(clipper.hidesAll(kSource.v.data(), kSource.count, clipper.occluders()));
  expectEveryPointHidden(clipper);

  // Lowered below the segments from the source's far edge, the block hides part only.
  const Box low = box({1.2, -1, 0.5}, {2.8, 2, 1.0});
  std::vector<OccluderPolygon> lowFaces;
  for (const auto& face : low.faces) lowFaces.push_back({&face, 0});
  const std::vector<SolidPlanes> lowSolids{low.planes};
  const std::vector<Vec3> lowCentres{low.centre};
  const ShadowClipper partial(kSource, kUp, receiver, kDown, lowFaces, lowSolids, &lowCentres);
  EXPECT_FALSE(partial.hidesAll(kSource.v.data(), kSource.count, partial.occluders()));
}

// A block seen from a point outside it hides the cone over its silhouette: one convex cone of four planes
// (one face seen) or six (two or three), the same region its front faces hide one by one.
TEST(SolidSilhouette, TheConeOverABoxHasItsOutlinesPlanes) {
  const Box block = box({0, 0, 0}, {1, 1, 1});
  std::vector<const std::vector<Vec3>*> outlines;
  for (const auto& face : block.faces) outlines.push_back(&face);
  std::vector<SolidPlanes> planes;
  const std::vector<int> solidOf = closedConvexSolids(outlines, planes);
  ASSERT_EQ(planes.size(), 1u);
  const std::vector<SolidShape> shapes = solidShapes(outlines, solidOf, 1);
  ASSERT_EQ(shapes[0].corners.size(), 8u);
  ASSERT_EQ(shapes[0].edges.size(), 12u);
  std::array<Vec3, 32> cone;
  EXPECT_EQ(silhouetteCone(shapes[0], {0.5, 0.5, 3}, 1e-12, cone.data(), 32), 4);    // one face seen
  EXPECT_EQ(silhouetteCone(shapes[0], {3, 0.5, 3}, 1e-12, cone.data(), 32), 6);      // two faces
  EXPECT_EQ(silhouetteCone(shapes[0], {3, 3, 3}, 1e-12, cone.data(), 32), 6);        // three faces
  EXPECT_EQ(silhouetteCone(shapes[0], {0.5, 0.5, 0.5}, 1e-12, cone.data(), 32), 0);  // inside
  const int m = silhouetteCone(shapes[0], {3, 2, 4}, 1e-12, cone.data(), 32);
  ASSERT_EQ(m, 6);
  for (int k = 0; k < m; ++k)  // inward: every corner on or inside every plane
    for (const Vec3& c : shapes[0].corners) EXPECT_GE(cone[k].dot(c - Vec3(3, 2, 4)), -1e-12);
}

// Cut by its silhouette or face by face, a block between two squares hides the same part from every point of
// the source, where it hides part of the receiver, all of it or nothing.
TEST(SolidSilhouette, HidesWhatTheFacesHideOneByOne) {
  const ConvexPolygon receiver = polygon({{-1, -1, 3}, {-1, 2, 3}, {2, 2, 3}, {2, -1, 3}});  // faces -z
  const Box block = box({0.3, 0.2, 1.0}, {0.9, 0.7, 1.6});
  const std::vector<OccluderPolygon> faces = block.occluders();
  const std::vector<SolidPlanes> solids{block.planes};
  const std::vector<Vec3> centres{block.centre};
  const ShadowClipper byFaces(kSource, kUp, receiver, kDown, faces, solids, &centres);
  const ShadowClipper bySilhouette(kSource, kUp, receiver, kDown, faces, solids, &centres, &block.shapes);
  for (double s = 0; s <= 1.0; s += 0.125)
    for (double t = 0; t <= 1.0; t += 0.125) {
      const Vec3 x{s, t, 0};
      const double expected = byFaces.hidden(x, byFaces.occluders());
      EXPECT_GT(expected, 0.0);
      EXPECT_NEAR(bySilhouette.hidden(x, bySilhouette.occluders()), expected, 1e-14) << s << ", " << t;
    }
}

// Four points at once (their hidden pieces' Lambert sums taken together) as one by one: two blocks, so that
// a point's receiver falls into several pieces, and points that see nothing, part or all of it hidden.
TEST(ShadowClipper, FourPointsAtOnceAsOneByOne) {
  const ConvexPolygon receiver = polygon({{0.2, 0.2, 3}, {0.2, 0.8, 3}, {0.8, 0.8, 3}, {0.8, 0.2, 3}});
  const Box left = box({0.1, 0.1, 1.0}, {0.45, 0.9, 1.4}), right = box({0.55, 0.3, 1.8}, {0.8, 0.6, 2.2});
  std::vector<OccluderPolygon> faces = left.occluders();
  for (OccluderPolygon o : right.occluders()) faces.push_back({o.polygon, 1});
  const std::vector<SolidPlanes> solids{left.planes, right.planes};
  const std::vector<Vec3> centres{left.centre, right.centre};
  std::vector<SolidShape> shapes{left.shapes[0], right.shapes[0]};
  const ShadowClipper clipper(kSource, kUp, receiver, kDown, faces, solids, &centres, &shapes);
  int partly = 0, wholly = 0;
  for (double s = 0; s <= 1.0; s += 0.1)
    for (double t = 0; t <= 1.0; t += 0.1) {
      const std::array<Vec3, 4> x{Vec3(s, t, 0), Vec3(t, s, 0), Vec3(1 - s, t, 0), Vec3(s, 1 - t, 0)};
      std::array<double, 4> four;
      std::array<bool, 4> whollyFour;
      clipper.hidden4(x.data(), clipper.occluders(), four.data(), whollyFour.data());
      for (std::size_t p = 0; p < 4; ++p) {
        bool whollyOne = false;
        const double one = clipper.hidden(x[p], clipper.occluders(), &whollyOne);
        EXPECT_NEAR(four[p], one, 1e-15 + 2e-15 * one) << x[p].transpose();
        EXPECT_EQ(whollyFour[p], whollyOne) << x[p].transpose();
        partly += one > 0 && !whollyOne;
        wholly += whollyOne;
      }
    }
  EXPECT_GT(partly, 100);
  EXPECT_GT(wholly, 0);
}

// A block given without its bottom (the Cornell box's) is closed by the face its open edges outline, and
// is then a solid; a closed box needs no such face; a lone flat patch gets one but is no solid (no volume).
TEST(ClosingFaces, ABlockWithoutItsBottomIsASolid) {
  const Box block = box({0, 0, 0}, {1, 2, 3});
  std::vector<const std::vector<Vec3>*> open, closed;
  for (const auto& face : block.faces) {
    closed.push_back(&face);
    if (!(face[0].z() == 0 && face[1].z() == 0 && face[2].z() == 0)) open.push_back(&face);  // no bottom
  }
  ASSERT_EQ(open.size(), 5u);
  EXPECT_TRUE(closingFaces(closed).empty());
  const std::vector<std::vector<Vec3>> closing = closingFaces(open);
  ASSERT_EQ(closing.size(), 1u);
  for (const Vec3& v : closing[0]) EXPECT_EQ(v.z(), 0.0);
  std::vector<const std::vector<Vec3>*> completed = open;
  completed.push_back(&closing[0]);
  std::vector<SolidPlanes> planes;
  const std::vector<int> solidOf = closedConvexSolids(completed, planes);
  ASSERT_EQ(planes.size(), 1u);
  for (int s : solidOf) EXPECT_EQ(s, 0);
  // The closing face faces out of the block: down.
  const std::vector<Vec3>& c = closing[0];
  EXPECT_LT((c[1] - c[0]).cross(c[2] - c[1]).z(), 0.0);

  const std::vector<Vec3> flat{{0, 0, 5}, {1, 0, 5}, {1, 1, 5}, {0, 1, 5}};
  std::vector<const std::vector<Vec3>*> lone{&flat};
  const std::vector<std::vector<Vec3>> lid = closingFaces(lone);
  ASSERT_EQ(lid.size(), 1u);
  lone.push_back(&lid[0]);
  closedConvexSolids(lone, planes);
  EXPECT_TRUE(planes.empty());
}

// solidMissesEverySegment: true only where no segment between the two squares meets the block (checked on
// grids of points), and it does say so for squares that share the side of one of the block's faces.
TEST(SolidMissesEverySegment, OnlyWhereNoSegmentMeetsTheBlock) {
  const Vec3 lo{0.4, 0.4, 0}, hi{0.6, 0.6, 0.5};
  const Box block = box(lo, hi);
  auto square = [](double x, double y, double z, double size) {
    return polygon({{x, y, z}, {x + size, y, z}, {x + size, y + size, z}, {x, y + size, z}});
  };
  auto meetsAny = [&](const ConvexPolygon& a, const ConvexPolygon& b) {
    return someSegmentMeetsBox(a, b, lo, hi, 5);
  };
  int misses = 0;
  for (double x = 0; x < 1; x += 0.1)
    for (double y : {0.0, 0.45, 0.8}) {
      const ConvexPolygon floor = square(x, y, 0, 0.1), ceiling = square(0.7, 0.45, 1, 0.1);
      if (!solidMissesEverySegment(floor.v.data(), 4, ceiling.v.data(), 4, block.planes, 1e-12)) continue;
      ++misses;
      EXPECT_FALSE(meetsAny(floor, ceiling)) << x << ", " << y;
    }
  EXPECT_GT(misses, 5);
  // Across the block: not proven (though some of these pairs do miss it, over the top).
  EXPECT_FALSE(solidMissesEverySegment(square(0, 0.45, 0, 0.1).v.data(), 4,
                                       square(0.9, 0.45, 1, 0.1).v.data(), 4, block.planes, 1e-12));
}

// Planes through an edge of one element and a corner of the other (faces of their hull) settle pairs that the
// block's own faces do not: a floor element beside the block and a wall element lower than its top, where
// no shadow region is bounded either way. Never where a segment between them meets the block.
TEST(SolidOutsideHullOf, OnlyWhereNoSegmentMeetsTheBlock) {
  const Vec3 lo{0.4, 0.4, 0}, hi{0.6, 0.6, 0.5};
  const Box block = box(lo, hi);
  const std::vector<Vec3>& corners = block.shapes[0].corners;
  auto floorSquare = [](double x, double y) {
    return polygon({{x, y, 0}, {x + 0.1, y, 0}, {x + 0.1, y + 0.1, 0}, {x, y + 0.1, 0}});
  };
  auto wallSquare = [](double y, double z) {  // on the wall x = 0, facing +x
    return polygon({{0, y, z}, {0, y + 0.1, z}, {0, y + 0.1, z + 0.1}, {0, y, z + 0.1}});
  };
  auto meetsAny = [&](const ConvexPolygon& a, const ConvexPolygon& b) {
    return someSegmentMeetsBox(a, b, lo, hi, 8);
  };
  int proven = 0, onlyByTheHull = 0, meeting = 0;
  for (double x = 0.05; x < 1; x += 0.1)
    for (double y = 0.05; y < 1; y += 0.1)
      for (double wallY : {0.0, 0.45, 0.8})
        for (double wallZ : {0.1, 0.3, 0.7}) {
          if (x + 0.1 > lo.x() && x < hi.x() && y + 0.1 > lo.y() && y < hi.y()) continue;  // under the block
          const ConvexPolygon floor = floorSquare(x, y), wall = wallSquare(wallY, wallZ);
          const bool outside = solidOutsideHullOf(floor.v.data(), 4, wall.v.data(), 4, corners.data(),
                                                  static_cast<int>(corners.size()), 1e-12);
          const bool meets = meetsAny(floor, wall);
          meeting += meets;
          if (!outside) continue;
          ++proven;
          onlyByTheHull += !solidMissesEverySegment(floor.v.data(), 4, wall.v.data(), 4, block.planes, 1e-12);
          EXPECT_FALSE(meets) << "floor at " << x << ", " << y << ", wall at " << wallY << ", " << wallZ;
        }
  EXPECT_GT(proven, 200);
  EXPECT_GT(onlyByTheHull, 50);
  EXPECT_GT(meeting, 50);  // and the block does stand between many of them
}

TEST(SegmentEntersSolid, ThroughBesideAndGrazing) {
  const Box block = box({0.4, 0.4, 0}, {0.6, 0.6, 0.5});
  EXPECT_TRUE(segmentEntersSolid({0, 0.5, 0.25}, {1, 0.5, 0.25}, block.planes, 1e-9));     // through
  EXPECT_FALSE(segmentEntersSolid({0, 0.7, 0.25}, {1, 0.7, 0.25}, block.planes, 1e-9));    // beside
  EXPECT_FALSE(segmentEntersSolid({0, 0.5, 0.25}, {0.3, 0.5, 0.25}, block.planes, 1e-9));  // ends before it
  // Along the top face: inside by nothing, within any eps of it.
  EXPECT_FALSE(segmentEntersSolid({0, 0.5, 0.5}, {1, 0.5, 0.5}, block.planes, 1e-9));
  EXPECT_TRUE(segmentEntersSolid({0, 0.5, 0.5}, {1, 0.5, 0.5}, block.planes, -1e-9));
  EXPECT_TRUE(segmentEntersSolid({0.5, 0.5, 0.2}, {0.5, 0.5, 0.3}, block.planes, 1e-9));  // wholly inside
}

}  // namespace
}  // namespace rt
