// The visibility events of one occluder (visibility_events.h): cut along them, the source falls into cells in
// each of which the hidden part keeps its form. Checked by what that promises: whether nothing, part or all
// of the receiver is hidden is the same at every point of a cell, and Gauss rules on a cell converge as on
// an analytic integrand, while on the uncut source, across the events, they do not.
#include "core/formfactor/quadrature/visibility_events.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "core/event_scenes.h"
#include "core/formfactor/quadrature/shadow_clipper.h"

namespace rt {
namespace {

using namespace event_scenes;

enum class Seen { Nothing, Part, All };

Seen hiddenAt(const ShadowClipper& clipper, const Vec3& x) {
  bool wholly = false;
  const double hidden = clipper.hidden(x, clipper.occluders(), &wholly);
  return wholly ? Seen::All : hidden > 0 ? Seen::Part : Seen::Nothing;
}

double rule(const ShadowClipper& clipper, const ConvexPolygon& cell, int n) {
  std::array<SourcePanel, ConvexPolygon::kInline> panels;
  const int count = panelsOf(cell.v.data(), cell.count, panels.data(), ConvexPolygon::kInline);
  double sum = 0;
  for (int p = 0; p < count; ++p)
    forEachGaussPoint(panels[static_cast<std::size_t>(p)], n,
                      [&](const Vec3& x, double w) { sum += w * clipper.hidden(x, clipper.occluders()); });
  return sum;
}

struct Cut {
  ShadowClipper clipper;
  std::vector<EventPlane> planes;
  std::vector<ConvexPolygon> cells;
  bool complete = false;
};

void cut(Cut& c) {
  c.complete = c.clipper.eventPlanes(kSource, c.clipper.occluders(), c.planes);
  ASSERT_TRUE(cutAlongEvents(kPanel, c.planes, 1e-12, 1000, c.cells));
}

class VisibilityEvents : public testing::TestWithParam<const Box*> {};

TEST_P(VisibilityEvents, WhatIsHiddenIsTheSameThroughoutEachCell) {
  const Box& kBlock = *GetParam();
  const std::vector<SolidPlanes> solids{kBlock.planes};
  const std::vector<Vec3> centres{kBlock.centre};
  Cut c{ShadowClipper(kSource, kUp, kReceiver, kDown, kBlock.occluders(), solids, &centres, &kBlock.shapes)};
  cut(c);
  ASSERT_TRUE(c.complete);
  EXPECT_GE(c.planes.size(), 2u);
  ASSERT_GE(c.cells.size(), 3u);
  int seen[3] = {0, 0, 0};
  for (const ConvexPolygon& cell : c.cells) {
    Vec3 centre = Vec3::Zero();
    for (int k = 0; k < cell.count; ++k) centre += cell.v[static_cast<std::size_t>(k)];
    centre /= cell.count;
    const Seen expected = hiddenAt(c.clipper, centre);
    ++seen[static_cast<int>(expected)];
    for (int k = 0; k < cell.count; ++k) {
      const Vec3 &a = cell.v[static_cast<std::size_t>(k)],
                 &b = cell.v[static_cast<std::size_t>((k + 1) % cell.count)];
      for (double s : {0.3, 0.7, 0.98}) {
        EXPECT_EQ(hiddenAt(c.clipper, centre + s * (a - centre)), expected) << "towards corner " << k;
        EXPECT_EQ(hiddenAt(c.clipper, centre + s * (0.5 * (a + b) - centre)), expected)
            << "towards edge " << k;
      }
    }
  }
  // The scene is made so that all three happen.
  EXPECT_GT(seen[static_cast<int>(Seen::Nothing)], 0);
  EXPECT_GT(seen[static_cast<int>(Seen::Part)], 0);
  EXPECT_GT(seen[static_cast<int>(Seen::All)], 0);
}

TEST_P(VisibilityEvents, RulesConvergeOnEachCellAsOnAnAnalyticIntegrand) {
  const Box& kBlock = *GetParam();
  const std::vector<SolidPlanes> solids{kBlock.planes};
  const std::vector<Vec3> centres{kBlock.centre};
  Cut c{ShadowClipper(kSource, kUp, kReceiver, kDown, kBlock.occluders(), solids, &centres, &kBlock.shapes)};
  cut(c);
  double cellsLow = 0, cellsHigh = 0;
  for (const ConvexPolygon& cell : c.cells) {
    const double low = rule(c.clipper, cell, 4), high = rule(c.clipper, cell, 10);
    EXPECT_NEAR(low, high, 1e-9) << "a cell of " << cell.count << " corners";
    cellsLow += low;
    cellsHigh += high;
  }
  // The uncut source, across the events, by the same rules: far apart.
  const double wholeLow = rule(c.clipper, kSource, 4), wholeHigh = rule(c.clipper, kSource, 10);
  EXPECT_GT(std::abs(wholeLow - wholeHigh), 1e-6);
  EXPECT_NEAR(cellsHigh, wholeHigh, 1e-4);
  EXPECT_NEAR(cellsLow, cellsHigh, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(SlabAndCorner, VisibilityEvents, testing::Values(&kSlab, &kCorner));

TEST(VisibilityEventPlanes, OnePolygonHasThemTwoOccludersDoNot) {
  const std::vector<SolidPlanes> none;
  const std::vector<Vec3> plate{{0.7, 0.3, 1.5}, {1.3, 0.3, 1.5}, {1.3, 0.8, 1.5}, {0.7, 0.8, 1.5}};
  Cut one{ShadowClipper(kSource, kUp, kReceiver, kDown, {{&plate, -1}}, none)};
  cut(one);
  EXPECT_TRUE(one.complete);
  EXPECT_GE(one.cells.size(), 3u);
  for (const ConvexPolygon& cell : one.cells)
    EXPECT_NEAR(rule(one.clipper, cell, 4), rule(one.clipper, cell, 10), 1e-9);

  const std::vector<Vec3> second{{0.2, 0.3, 2.2}, {0.9, 0.3, 2.2}, {0.9, 0.5, 2.2}, {0.2, 0.5, 2.2}};
  const ShadowClipper two(kSource, kUp, kReceiver, kDown, {{&plate, -1}, {&second, -1}}, none);
  ASSERT_EQ(two.occluders().size(), 2u);
  std::vector<EventPlane> planes;
  EXPECT_FALSE(two.eventPlanes(kSource, two.occluders(), planes));
}

// Two whole blocks: each one's planes, and those through a silhouette corner of one and a silhouette edge of
// the other (where the shadow of the corner crosses the shadow of the edge).
TEST(VisibilityEventPlanes, TwoWholeBlocksHaveEachOnesAndTheCornerEdgePlanesBetweenThem) {
  const Box low = box({0.3, -1, 1.2}, {0.9, 0.45, 1.4}), high = box({0.1, 0.55, 1.8}, {0.7, 2, 2.0});
  const std::vector<SolidPlanes> solids{low.planes, high.planes};
  const std::vector<Vec3> centres{low.centre, high.centre};
  const std::vector<SolidShape> shapes{low.shapes[0], high.shapes[0]};
  std::vector<OccluderPolygon> occluders = low.occluders();
  for (OccluderPolygon o : high.occluders()) occluders.push_back({o.polygon, 1});
  const ShadowClipper both(kSource, kUp, kReceiver, kDown, occluders, solids, &centres, &shapes);
  ASSERT_EQ(both.occluders().size(), 12u);  // none culled: the scene is made so that both shade
  std::vector<EventPlane> planes;
  ASSERT_TRUE(both.eventPlanes(kSource, both.occluders(), planes));
  // Each block's own planes, as the clipper finds them for it alone, are among them.
  std::size_t own = 0;
  for (int solid : {0, 1}) {
    std::vector<int> ofOne;
    for (int k : both.occluders())
      if (both.solidOf(k) == solid) ofOne.push_back(k);
    std::vector<EventPlane> alone;
    ASSERT_TRUE(both.eventPlanes(kSource, ofOne, alone));
    own += alone.size();
    for (const EventPlane& plane : alone) {
      bool found = false;
      for (const EventPlane& p : planes)
        found |= (p.origin - plane.origin).norm() < 1e-12 && p.normal.cross(plane.normal).norm() < 1e-12;
      EXPECT_TRUE(found) << "a plane of block " << solid;
    }
  }
  // The rest pass through a corner of one block and an edge of the other.
  ASSERT_GT(planes.size(), own);
  const std::array<const Box*, 2> boxes{&low, &high};
  for (std::size_t k = own; k < planes.size(); ++k) {
    bool throughCornerAndEdge = false;
    for (std::size_t s = 0; s < 2; ++s)
      for (const Vec3& corner : boxes[s]->shapes[0].corners)
        for (const SolidShape::Edge& edge : boxes[1 - s]->shapes[0].edges) {
          const Vec3 &a = boxes[1 - s]->shapes[0].corners[static_cast<std::size_t>(edge.a)],
                     &b = boxes[1 - s]->shapes[0].corners[static_cast<std::size_t>(edge.b)];
          const Vec3 n = planes[k].normal.normalized();
          throughCornerAndEdge |= std::abs(n.dot(corner - planes[k].origin)) < 1e-12 &&
                                  std::abs(n.dot(a - planes[k].origin)) < 1e-12 &&
                                  std::abs(n.dot(b - planes[k].origin)) < 1e-12;
        }
    EXPECT_TRUE(throughCornerAndEdge) << k;
  }
}

// An event that happens on part of its line only cuts the cells that part meets.
TEST(VisibilityEventPlanes, ACellTheEventsSegmentMissesIsNotCut) {
  const EventPlane across{{0.5, 0, 0}, {1, 0, 0}};  // the line x = 0.5, all of it
  EventPlane low = across, high = across;
  low.from = {0.5, 0.1, 0}, low.to = {0.5, 0.3, 0}, low.bounded = true;  // on the half y < 0.5 only
  high.from = {0.5, 0.7, 0}, high.to = {0.5, 0.9, 0}, high.bounded = true;
  const EventPlane half{{0, 0.5, 0}, {0, 1, 0}};  // first the square into y < 0.5 and y > 0.5
  for (const auto& [second, expected] : {std::pair{across, 4u}, {low, 3u}, {high, 3u}}) {
    std::vector<ConvexPolygon> cells;
    ASSERT_TRUE(cutAlongEvents(kPanel, {half, second}, 1e-12, 64, cells));
    EXPECT_EQ(cells.size(), expected);
  }
  EventPlane beyond = across;  // a segment beyond the square: no cut at all
  beyond.from = {0.5, 1.5, 0}, beyond.to = {0.5, 2, 0}, beyond.bounded = true;
  std::vector<ConvexPolygon> cells;
  ASSERT_TRUE(cutAlongEvents(kPanel, {beyond}, 1e-12, 64, cells));
  EXPECT_EQ(cells.size(), 1u);
}

TEST(VisibilityEventPlanes, CellsBeyondTheBoundAreRefused) {
  const std::vector<SolidPlanes> solids{kSlab.planes};
  const std::vector<Vec3> centres{kSlab.centre};
  const ShadowClipper clipper(kSource, kUp, kReceiver, kDown, kSlab.occluders(), solids, &centres,
                              &kSlab.shapes);
  std::vector<EventPlane> planes;
  ASSERT_TRUE(clipper.eventPlanes(kSource, clipper.occluders(), planes));
  std::vector<ConvexPolygon> cells(2);  // a caller's cells from before are kept
  EXPECT_FALSE(cutAlongEvents(kPanel, planes, 1e-12, 2, cells));
  EXPECT_EQ(cells.size(), 2u);
}

}  // namespace
}  // namespace rt
