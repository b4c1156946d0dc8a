#include "core/refine/discontinuity.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/refine/constrained_triangulation.h"
#include "core/refine/refine.h"
#include "refine_test_scenes.h"

namespace rt {
namespace {

// In test::shadowScene a floor point p is the shadow of occluder point x from light point l: p = 2x - l. With
// the occluder's edges at +-0.5 and the light's at +-0.25, the critical lines are x or y = +-0.75 (umbra) and
// +-1.25 (outer penumbra), each running over [-1.25, 1.25] in the other coordinate.
constexpr double kLines[] = {-1.25, -0.75, 0.75, 1.25};

bool onLine(double v) {
  for (double l : kLines)
    if (std::abs(v - l) < 1e-9) return true;
  return false;
}

TEST(RefineDiscontinuity, SquareLightSquareOccluderGivesTheHandComputedLines) {
  const Scene s = test::shadowScene();
  const std::vector<CriticalSegment> segments = criticalSegments(s, 2, 0.0);
  ASSERT_FALSE(segments.empty());
  int ve = 0, ev = 0;
  for (const CriticalSegment& c : segments) {
    EXPECT_NEAR(c.a.z(), 0.0, 1e-12);
    EXPECT_NEAR(c.b.z(), 0.0, 1e-12);
    const bool vertical = std::abs(c.a.x() - c.b.x()) < 1e-9;    // x = const
    const bool horizontal = std::abs(c.a.y() - c.b.y()) < 1e-9;  // y = const
    ASSERT_TRUE(vertical || horizontal);
    EXPECT_TRUE(vertical ? onLine(c.a.x()) : onLine(c.a.y())) << c.a.transpose() << " - " << c.b.transpose();
    for (const Vec3& p : {c.a, c.b}) {
      EXPECT_LE(std::abs(p.x()), 1.25 + 1e-9);
      EXPECT_LE(std::abs(p.y()), 1.25 + 1e-9);
    }
    (c.kind == CriticalSegment::Kind::VE ? ve : ev)++;
  }
  EXPECT_GT(ve, 0);
  EXPECT_GT(ev, 0);
  // Each of the 8 lines is covered over its whole extent by the union of segments.
  for (double line : kLines)
    for (int axis = 0; axis < 2; ++axis)
      for (double t = -1.24; t <= 1.24; t += 0.01) {
        bool covered = false;
        for (const CriticalSegment& c : segments) {
          const double fixedA = axis == 0 ? c.a.x() : c.a.y(), fixedB = axis == 0 ? c.b.x() : c.b.y();
          if (std::abs(fixedA - line) > 1e-9 || std::abs(fixedB - line) > 1e-9) continue;
          const double lo = std::min(axis == 0 ? c.a.y() : c.a.x(), axis == 0 ? c.b.y() : c.b.x());
          const double hi = std::max(axis == 0 ? c.a.y() : c.a.x(), axis == 0 ? c.b.y() : c.b.x());
          covered |= t >= lo - 1e-9 && t <= hi + 1e-9;
        }
        EXPECT_TRUE(covered) << "line " << (axis == 0 ? "x" : "y") << " = " << line << " at " << t;
      }
}

TEST(RefineDiscontinuity, SegmentClippingToAConvexPolygon) {
  const Polygon square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  Vec3 a(-1, 0.5, 0), b(2, 0.5, 0);
  ASSERT_TRUE(clipSegmentToPolygon(a, b, square, Vec3(0, 0, 1)));
  EXPECT_NEAR((a - Vec3(0, 0.5, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((b - Vec3(1, 0.5, 0)).norm(), 0, 1e-12);
  Vec3 c(2, 2, 0), d(3, 2, 0);
  EXPECT_FALSE(clipSegmentToPolygon(c, d, square, Vec3(0, 0, 1)));
}

TEST(RefineDiscontinuity, FallbackTriangulationRespectsTheConstraints) {
  PlanarDomain d;
  d.boundary = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  d.constraints = {{{1, 0.5}, {1, 3.5}}, {{0.5, 2.2}, {3.5, 2.2}}};
  d.maxEdge = 1.0;
  const PlanarTriangulation t = cutConvexDomain(d);
  double area = 0;
  for (const auto& tri : t.triangles) {
    const Vec2 a = t.points[tri[0]], b = t.points[tri[1]], c = t.points[tri[2]];
    const double twice = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    EXPECT_GT(twice, 0);  // counter-clockwise
    area += twice / 2;
    // No triangle straddles x = 1 within the constraint's span.
    const double lo = std::min({a.x(), b.x(), c.x()}), hi = std::max({a.x(), b.x(), c.x()});
    const double ylo = std::min({a.y(), b.y(), c.y()});
    if (ylo > 0.5 && ylo < 3.4) {
      EXPECT_FALSE(lo < 1 - 1e-9 && hi > 1 + 1e-9);
    }
  }
  EXPECT_NEAR(area, 16.0, 1e-9);
}

TEST(RefineDiscontinuity, NoElementStraddlesTheUmbraBoundary) {
  RefineOptions o;
  o.mode = RefineMode::Discontinuity;
  o.initialMaxEdge = 0.5;
  const RefinedSolution s = solveRefined(test::shadowScene(), o);
  ASSERT_FALSE(s.discontinuities.empty());
  double floorArea = 0;
  for (std::size_t e = 0; e < s.mesh.size(); ++e) {
    const Element& el = s.mesh.elements[e];
    if (el.patch != 2) continue;
    floorArea += el.area;
    const Polygon p = s.mesh.polygon(static_cast<int>(e));
    double lo = 1e9, hi = -1e9, ylo = 1e9, yhi = -1e9;
    for (const Vec3& v : p)
      lo = std::min(lo, v.x()), hi = std::max(hi, v.x()), ylo = std::min(ylo, v.y()),
      yhi = std::max(yhi, v.y());
    if (yhi < 1.25 && ylo > -1.25) {
      EXPECT_FALSE(lo < 0.75 - 1e-9 && hi > 0.75 + 1e-9) << "element " << e << " crosses x = 0.75";
      EXPECT_FALSE(lo < -1.25 + 1e-9 - 2e-9 && hi > -1.25 + 1e-9) << "element " << e << " crosses x = -1.25";
    }
  }
  EXPECT_NEAR(floorArea, 16.0, 1e-9);
  // The floor under the occluder's middle is dark, far out it is lit.
  const Rgb umbra = radiosityAt(s, 2, Vec3(0, 0, 0));
  const Rgb lit = radiosityAt(s, 2, Vec3(1.8, 0, 0));
  EXPECT_LT(umbra[0], 0.05 * lit[0]);
}

}  // namespace
}  // namespace rt
