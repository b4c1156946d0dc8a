// Hidden forms (ShadowClipper::formOf): found at a cell's centre, they place the hidden part's outline at
// every other point of the cell without clipping. Checked against the clip itself, inside the cells, and for
// the guard that refuses a form taken where it does not fit.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/event_scenes.h"
#include "core/formfactor/analytic.h"
#include "core/formfactor/lambert_four.h"
#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/quadrature/visibility_events.h"

namespace rt {
namespace {

using namespace event_scenes;

struct BlockPair {
  explicit BlockPair(const Box& block)
      : solids{block.planes},
        centres{block.centre},
        clipper(kSource, kUp, kReceiver, kDown, block.occluders(), solids, &centres, &block.shapes) {
    std::vector<EventPlane> planes;
    EXPECT_TRUE(clipper.eventPlanes(kSource, clipper.occluders(), planes));
    EXPECT_TRUE(cutAlongEvents(kPanel, planes, 1e-12, 1000, cells)) << planes.size() << " planes";
  }
  std::vector<SolidPlanes> solids;
  std::vector<Vec3> centres;
  ShadowClipper clipper;
  std::vector<ConvexPolygon> cells;
};

Vec3 centreOf(const ConvexPolygon& cell) {
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < cell.count; ++k) c += cell.v[static_cast<std::size_t>(k)];
  return c / cell.count;
}

class HiddenForm : public testing::TestWithParam<const Box*> {};

TEST_P(HiddenForm, PlacesTheClippedOutlineThroughoutEachCell) {
  BlockPair s(*GetParam());
  ASSERT_GE(s.cells.size(), 3u);
  int placed = 0, partly = 0;
  for (const ConvexPolygon& cell : s.cells) {
    const Vec3 centre = centreOf(cell);
    ShadowClipper::HiddenForm form;
    double found = -1;  // what the clip that finds the form hides, where it hides part
    ASSERT_TRUE(s.clipper.formOf(centre, s.clipper.occluders(), form, &found));
    bool wholly = false;
    const double clipped = s.clipper.hidden(centre, s.clipper.occluders(), &wholly);
    EXPECT_EQ(form.wholly, wholly);
    EXPECT_EQ(form.count >= 3, clipped > 0);
    if (form.count >= 3 && !form.wholly) {
      EXPECT_NEAR(found, clipped, 1e-14);
    }
    partly += form.count >= 3 && !form.wholly;
    // Points all over the cell: towards each corner from the centre, and between corners.
    for (int k = 0; k < cell.count; ++k)
      for (double t : {0.2, 0.5, 0.8, 0.98}) {
        const Vec3 &a = cell.v[static_cast<std::size_t>(k)],
                   &b = cell.v[static_cast<std::size_t>((k + 1) % cell.count)];
        for (const Vec3& x : {Vec3(centre + t * (a - centre)), Vec3(centre + t * (0.5 * (a + b) - centre))}) {
          double value = -1;
          ASSERT_TRUE(s.clipper.hidden(x, form, value)) << "at " << x.transpose();
          EXPECT_NEAR(value, s.clipper.hidden(x, s.clipper.occluders()), 1e-14) << "at " << x.transpose();
          ++placed;
        }
      }
  }
  EXPECT_GT(partly, 0);
  EXPECT_GT(placed, 50);
}

// Outside its cell a form no longer fits, and is used only inside it. The guard (cuts within their edges, an
// outline that turns one way) is a net for cells cut short of an event by their margins, not a proof: it
// refuses the form at many points beyond its cell, and wherever it does accept one, the cell's own points
// above are where the answer is checked.
TEST_P(HiddenForm, IsRefusedWhereItFoldsOrOverruns) {
  BlockPair s(*GetParam());
  int refused = 0;
  for (const ConvexPolygon& cell : s.cells) {
    ShadowClipper::HiddenForm form;
    ASSERT_TRUE(s.clipper.formOf(centreOf(cell), s.clipper.occluders(), form));
    if (form.count < 3 || form.wholly) continue;
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        double value = -1;
        refused += !s.clipper.hidden(Vec3(0.025 + 0.95 * i / 20, 0.025 + 0.95 * j / 20, 0), form, value);
      }
  }
  EXPECT_GT(refused, 50);
}

TEST_P(HiddenForm, FourPointsAtOnceAsOneByOne) {
  BlockPair s(*GetParam());
  for (const ConvexPolygon& cell : s.cells) {
    const Vec3 centre = centreOf(cell);
    ShadowClipper::HiddenForm form;
    ASSERT_TRUE(s.clipper.formOf(centre, s.clipper.occluders(), form));
    std::array<Vec3, 4> x;
    for (std::size_t p = 0; p < 4; ++p)
      x[p] = centre + 0.6 * (cell.v[p % static_cast<std::size_t>(cell.count)] - centre);
    std::array<double, 4> four;
    ASSERT_TRUE(s.clipper.hidden4(x.data(), form, four.data()));
    for (std::size_t p = 0; p < 4; ++p) {
      double one = -1;
      ASSERT_TRUE(s.clipper.hidden(x[p], form, one));
      EXPECT_NEAR(four[p], one, 1e-15 + 1e-13 * one);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Blocks, HiddenForm, testing::Values(&kSlab, &kCorner));

TEST(LambertFour, AsFourScalarSums) {
  // Four points above a pentagon and a quadrilateral with an edge through the fourth point's line of sight.
  const std::array<Vec3, 4> points{Vec3(0.1, 0.2, 0), Vec3(0.5, -0.3, 0.1), Vec3(-2, 1, 0.5), Vec3(0, 0, 0)};
  const Vec3 normal(0, 0, 1);
  constexpr int kStride = 8;
  std::array<Vec3, 4 * kStride> corners;
  const std::array<Vec3, 5> pentagon{Vec3(0, 0, 2), Vec3(0, 1, 2.1), Vec3(1, 1.5, 2), Vec3(1.5, 0.5, 1.9),
                                     Vec3(1, -0.5, 2)};
  for (std::size_t p = 0; p < 4; ++p)
    for (std::size_t k = 0; k < 5; ++k) corners[p * kStride + k] = pentagon[k] + Vec3(0.1 * p, 0, 0);
  std::array<double, 4> four;
  lambertContourSum4(points.data(), normal, corners.data(), kStride, 5, four.data());
  for (std::size_t p = 0; p < 4; ++p) {
    const double one = lambertContourSum(points[p], normal, &corners[p * kStride], 5);
    EXPECT_NEAR(four[p], one, 2e-15 * std::abs(one)) << p;
  }
  // One polygon for all four (stride 0), with an edge seen end-on from the last point: no solid angle.
  const std::array<Vec3, 4> quad{Vec3(0, 0, 1), Vec3(0, 0, 2), Vec3(1, 0, 2), Vec3(1, 1, 1)};
  lambertContourSum4(points.data(), normal, quad.data(), 0, 4, four.data());
  for (std::size_t p = 0; p < 4; ++p) {
    const double one = lambertContourSum(points[p], normal, quad.data(), 4);
    EXPECT_TRUE(std::isfinite(four[p]));
    EXPECT_NEAR(four[p], one, 2e-15 * std::abs(one) + 1e-17) << p;
  }
}

// Polygons of different corner counts in the four lanes (the shorter padded with their first corner), and a
// lane with none.
TEST(LambertFour, PolygonsOfDifferentCornerCounts) {
  const std::array<Vec3, 4> points{Vec3(0.1, 0.2, 0), Vec3(0.5, -0.3, 0.1), Vec3(-2, 1, 0.5), Vec3(0, 0, 0)};
  const Vec3 normal(0, 0, 1);
  const std::array<Vec3, 5> pentagon{Vec3(0, 0, 2), Vec3(0, 1, 2.1), Vec3(1, 1.5, 2), Vec3(1.5, 0.5, 1.9),
                                     Vec3(1, -0.5, 2)};
  const std::array<Vec3, 3> triangle{Vec3(0, 0, 1), Vec3(0, 1, 1), Vec3(1, 0, 1.2)};
  const std::array<Vec3, 4> quad{Vec3(-1, -1, 3), Vec3(-1, 1, 3), Vec3(1, 1, 3), Vec3(1, -1, 3)};
  const Vec3* polygons[4] = {triangle.data(), pentagon.data(), quad.data(), quad.data()};
  const int counts[4] = {3, 5, 4, 0};
  std::array<double, 4> four;
  lambertContourSum4(points.data(), normal, polygons, counts, four.data());
  for (std::size_t p = 0; p < 3; ++p) {
    const double one = lambertContourSum(points[p], normal, polygons[p], counts[p]);
    EXPECT_NEAR(four[p], one, 2e-15 * std::abs(one)) << p;
  }
  EXPECT_EQ(four[3], 0.0);
}

}  // namespace
}  // namespace rt
