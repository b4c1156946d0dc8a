// Visibility events on the source element: where they are found, that splitting along them tiles the source,
// and that entries whose integrand jumps inside the source (an occluder standing on it) come out right.
#include "exact/visibility_events.h"

#include <gtest/gtest.h>

#include "core/polygon.h"
#include "exact/adaptive_cubature.h"
#include "exact/exact_reference.h"
#include "exact/exact_scenes.h"
#include "exact/geometry_util.h"

namespace rt::exact {
namespace {

const Polygon kFloor{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};    // z = 0, facing +z
const Polygon kCeiling{{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}};  // z = 1, facing -z
const Vec3 kUp(0, 0, 1);

// Distance of p from the line through the segment, in the plane z = 0.
double distanceFromLine(const EventSegment& e, const Vec3& p) {
  const Vec3 d = (e.b - e.a).normalized();
  return (p - e.a).cross(d).norm();
}

bool onSomeLine(const std::vector<EventSegment>& events, const Vec3& p, const Vec3& q) {
  for (const EventSegment& e : events)
    if (distanceFromLine(e, p) < 1e-9 && distanceFromLine(e, q) < 1e-9) return true;
  return false;
}

TEST(VisibilityEvents, UnoccludedPairsHaveNone) {
  const Mesh mesh = test::meshFromPolygons({kFloor, kCeiling});
  EXPECT_TRUE(visibilityEvents(setUpPair(mesh, 0, 1)).empty());
}

TEST(VisibilityEvents, APlateCastsTheLinesOfItsPenumbraAndUmbra) {
  // A plate [0.4, 0.6]^2 at height 0.5 between floor and ceiling: the receiver's corners and the plate's
  // edges line up along x = 2 * 0.4 - 1 = -0.2 (outside), x = 2 * 0.6 - 0 = 1.2 (outside), and x = 0.8 - 0 =
  // 0.8 and 1.2 - 1 = 0.2 (inside the source), and the same in y.
  const Polygon plate = {{0.4, 0.4, 0.5}, {0.4, 0.6, 0.5}, {0.6, 0.6, 0.5}, {0.6, 0.4, 0.5}};
  const Mesh mesh = test::meshFromPolygons({kFloor, kCeiling, plate});
  const std::vector<EventSegment> events = visibilityEvents(setUpPair(mesh, 0, 1));
  ASSERT_FALSE(events.empty());
  for (const EventSegment& e : events) {
    EXPECT_NEAR(e.a.z(), 0, 1e-12);
    EXPECT_NEAR(e.b.z(), 0, 1e-12);
    for (const Vec3& p : {e.a, e.b}) {
      EXPECT_GE(p.x(), -1e-12);
      EXPECT_LE(p.x(), 1 + 1e-12);
    }
  }
  for (double c : {0.2, 0.8}) {
    EXPECT_TRUE(onSomeLine(events, {c, 0, 0}, {c, 1, 0})) << "x = " << c;
    EXPECT_TRUE(onSomeLine(events, {0, c, 0}, {1, c, 0})) << "y = " << c;
  }
}

TEST(VisibilityEvents, InnerMeshLinesOfAnOccluderAreNoEvents) {
  // A floor element, a ceiling element and the plate as 4 x 4 elements give the event lines of the whole
  // plate: its inner mesh lines x, y = 0.45, 0.5, 0.55 bound no shadow.
  const Polygon plate = {{0.4, 0.4, 0.5}, {0.4, 0.6, 0.5}, {0.6, 0.6, 0.5}, {0.6, 0.4, 0.5}};
  const Mesh room = test::meshFromPolygons({kFloor, kCeiling, plate}, 4);
  int source = -1, receiver = -1;
  for (std::size_t i = 0; i < room.size(); ++i) {
    const Vec3 c = polygonCentroid(room.polygon(i));
    if (c.z() == 0 && c.x() < 0.25 && c.y() < 0.25) source = static_cast<int>(i);
    if (c.z() == 1 && c.x() > 0.75 && c.y() > 0.75) receiver = static_cast<int>(i);
  }
  ASSERT_GE(source, 0);
  ASSERT_GE(receiver, 0);
  const PairGeometry pair = setUpPair(room, source, receiver);
  ASSERT_EQ(pair.occluders.size(), 16u);
  const std::vector<EventSegment> events = visibilityEvents(pair);
  const std::vector<EventSegment> whole = visibilityEvents(
      setUpPair(test::meshFromPolygons({room.polygon(source), room.polygon(receiver), plate}), 0, 1));
  ASSERT_FALSE(whole.empty());
  ASSERT_FALSE(events.empty());
  for (const EventSegment& e : events) EXPECT_TRUE(onSomeLine(whole, e.a, e.b));
}

// Length of the part of segment e strictly inside the convex cell (in the plane z = 0).
double lengthInside(const EventSegment& e, const Polygon& cell) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& c : cell) centre += c;
  centre /= static_cast<double>(cell.size());
  double lo = 0, hi = 1;
  for (std::size_t k = 0; k < cell.size(); ++k) {
    Vec3 m = kUp.cross(cell[(k + 1) % cell.size()] - cell[k]);
    if (m.dot(centre - cell[k]) < 0) m = -m;
    const double f0 = m.dot(e.a - cell[k]), f1 = m.dot(e.b - e.a);
    if (f1 == 0) {
      if (f0 <= 0) return 0;
    } else if (f1 > 0) {
      lo = std::max(lo, -f0 / f1);
    } else {
      hi = std::min(hi, -f0 / f1);
    }
  }
  return hi > lo ? (hi - lo) * (e.b - e.a).norm() : 0;
}

TEST(VisibilityEvents, SplittingTilesTheDomainAndLeavesNoEventInsideACell) {
  const Polygon plate = {{0.3, 0.35, 0.4}, {0.35, 0.7, 0.45}, {0.7, 0.65, 0.5}, {0.65, 0.3, 0.45}};
  const Mesh mesh = test::meshFromPolygons({kFloor, kCeiling, plate});
  const PairGeometry pair = setUpPair(mesh, 0, 1);
  const std::vector<EventSegment> events = visibilityEvents(pair);
  ASSERT_FALSE(events.empty());
  const double margin = 1e-9;
  const std::vector<Polygon> cells = splitAlongEvents(pair.integrationDomain, kUp, events, margin);
  EXPECT_GT(cells.size(), 4u);
  double area = 0;
  for (const Polygon& cell : cells) {
    area += polygonArea(cell);
    // A segment may run along a cell's border, never through its interior.
    Polygon shrunk;
    const Vec3 c = polygonCentroid(cell);
    for (const Vec3& v : cell) shrunk.push_back(c + (1 - 1e-6) * (v - c));
    for (const EventSegment& e : events) EXPECT_LT(lengthInside(e, shrunk), 1e-7);
  }
  EXPECT_NEAR(area, 1.0, 1e-13);
}

TEST(VisibilityEvents, AnOccluderStandingOnTheSourceIsIntegratedExactly) {
  // A block standing on the floor covers x > 0.6 of the source up to the ceiling's height: that part sees
  // nothing, the rest sees the ceiling's part x < 0.6 unobstructed. F jumps along x = 0.6 inside the source,
  // the contact line, which is an event line: the entry is the unoccluded integral over the free part.
  // (Without the split, cubature cells straddle the jump and the estimate settled 3e-5 relative off at a
  // requested 1e-9.)
  std::vector<Polygon> polygons{kFloor, {{0, 0, 1}, {0, 1, 1}, {0.6, 1, 1}, {0.6, 0, 1}}};
  for (const Polygon& face : test::boxFaces({0.6, -0.5, 0}, {1.5, 1.5, 1}, false)) polygons.push_back(face);
  const Mesh mesh = test::meshFromPolygons(polygons);
  const Polygon freeHalf{{0, 0, 0}, {0.6, 0, 0}, {0.6, 1, 0}, {0, 1, 0}};
  CubatureSettings settings;
  settings.order = 8;
  settings.tolerance = [](double estimate) { return 1e-13 * std::abs(estimate); };
  const double reference =
      AdaptiveCubature(settings)
          .integrate(freeHalf,
                     [&](const Vec3& x) { return pointToPolygonFormFactor(x, kUp, mesh.polygon(1)); })
          .value;
  ExactOptions options = exactOptionsFor(1e-9);
  options.occludedTolerance = 1e-9;
  const EntryResult entry = elementFormFactor(mesh, 0, 1, options);
  EXPECT_TRUE(entry.occluded);
  EXPECT_GT(entry.eventCells, 1);
  EXPECT_NEAR(entry.value, reference, 1e-9 * reference);
}

// The Cornell box's short block standing with one corner inside a floor element, and an element of the far
// wall: from the floor next to that corner the wall is hidden by the block on one side of a thin wedge and
// seen on the other, the wedge between the event lines from the corner through the wall element's vertical
// edges. A cut along one of them kept the corner twice, ~1e-12 apart, and the direction between the two
// copies bounded the next line's chord to nothing: the wedge went uncut and the entry settled 2.2 % low
// (1.33770e-4) with an error estimate of 1e-14. A brute-force double grid with segment-against-block
// visibility (160 x 160 points on each element) gives 1.36824e-4, the quadrature method at 1e-8 1.368226e-4.
TEST(VisibilityEvents, ABlocksCornerInsideTheSourceIsCutAlongEveryLineFromIt) {
  std::vector<Polygon> polygons{
      {{111.2, 0, 83.88}, {139, 0, 83.88}, {139, 0, 55.92}, {111.2, 0, 55.92}},  // floor, facing +y
      {{556, 246.96, 111.84}, {556, 274.4, 111.84}, {556, 274.4, 83.88}, {556, 246.96, 83.88}},  // wall, -x
      {{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}},  // the block: top and sides
      {{130, 0, 65}, {82, 0, 225}, {82, 165, 225}, {130, 165, 65}},
      {{82, 0, 225}, {240, 0, 272}, {240, 165, 272}, {82, 165, 225}},
      {{240, 0, 272}, {290, 0, 114}, {290, 165, 114}, {240, 165, 272}},
      {{290, 0, 114}, {130, 0, 65}, {130, 165, 65}, {290, 165, 114}}};
  const Mesh mesh = test::meshFromPolygons(polygons);
  ExactOptions options = exactOptionsFor(1e-9);
  options.occludedTolerance = 1e-9;
  const EntryResult entry = elementFormFactor(mesh, 0, 1, options);
  EXPECT_TRUE(entry.occluded);
  EXPECT_NEAR(entry.value, 1.368226e-4, 1e-10);
  // No event line crosses a cell's inside.
  const PairGeometry pair = setUpPair(mesh, 0, 1);
  const std::vector<EventSegment> events = visibilityEvents(pair);
  for (const Polygon& cell : splitAlongEvents(pair.integrationDomain, pair.sourceNormal, events, 1e-9)) {
    Polygon shrunk;
    const Vec3 c = polygonCentroid(cell);
    for (const Vec3& v : cell) shrunk.push_back(c + (1 - 1e-6) * (v - c));
    for (const EventSegment& e : events) EXPECT_LT(lengthInside(e, shrunk), 1e-5);
  }
}

}  // namespace
}  // namespace rt::exact
