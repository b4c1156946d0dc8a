// Occluded configurations with independent references: a full occluder (F exactly 0), an occluder touching
// the source, occluders straddling the source or receiver plane, several overlapping occluders, occluders
// split into elements. References use Lambert's formula on rectangles whose visible part is known in closed
// form, integrated with the same cubature but without any visibility computation.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "exact/adaptive_cubature.h"
#include "exact/exact_reference.h"
#include "exact/exact_scenes.h"

namespace rt::exact {
namespace {

const Polygon kFloor{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};    // z = 0, facing +z
const Polygon kCeiling{{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}};  // z = 1, facing -z
const Vec3 kUp(0, 0, 1);

Polygon rectangleAtHeight(double x0, double x1, double y0, double y1, double z) {
  return {{x0, y0, z}, {x0, y1, z}, {x1, y1, z}, {x1, y0, z}};  // facing -z, like the ceiling
}

// (1/A) integral over `domain` of f, to 1e-12 relative, split into the given pieces (kinks on their borders).
double referenceIntegral(const std::vector<Polygon>& pieces, const std::function<double(const Vec3&)>& f) {
  CubatureSettings settings;
  settings.order = 8;
  settings.maxEvaluations = 4000000;
  settings.tolerance = [](double estimate) { return 1e-12 * std::max(std::abs(estimate), 1e-6); };
  const AdaptiveCubature cubature(settings);
  double total = 0;
  for (const Polygon& piece : pieces) total += cubature.integrate(piece, f).value;
  return total;
}

// Entries to 1e-7 with the double-precision convex split (fast); the exact CGAL path is held to the same
// values point by point in SplitAndExactBooleansAgree.
ExactOptions splitOptions() {
  ExactOptions options;
  options.booleans = Booleans::Split;
  return options;
}

TEST(Occlusion, FullOccluderGivesExactlyZero) {
  const Polygon blocker = rectangleAtHeight(-1, 2, -1, 2, 0.5);
  const Mesh mesh = test::meshFromPolygons({kFloor, kCeiling, blocker});
  const EntryResult entry = elementFormFactor(mesh, 0, 1, splitOptions());
  EXPECT_TRUE(entry.occluded);
  EXPECT_EQ(entry.value, 0.0);
  EXPECT_EQ(entry.errorEstimate, 0.0);
  EXPECT_EQ(entry.evaluations, 0);  // proven wholly hidden from the corners: no cubature at all
  // A plate that leaves a sliver of the ceiling in view from one corner of the floor is not proven hidden.
  const Mesh sliver = test::meshFromPolygons({kFloor, kCeiling, rectangleAtHeight(-1, 0.99, -1, 2, 0.5)});
  const EntryResult partial = elementFormFactor(sliver, 0, 1, splitOptions());
  EXPECT_GT(partial.evaluations, 0);
  EXPECT_GT(partial.value, 0.0);
  const VisibleRegion region = visibleRegion(mesh, 0, Vec3(0.3, 0.6, 0), 1);
  EXPECT_TRUE(region.facing);
  EXPECT_TRUE(region.visible.empty());
  EXPECT_EQ(region.formFactor, 0.0);
  EXPECT_GT(region.unoccludedFormFactor, 0.1);
  ASSERT_EQ(region.occluderProjections.size(), 1u);
}

// A wide vertical wall in the plane x = 0.5 from height z0 to z1 (two-sided), between floor and ceiling. From
// a floor point at x = p < 0.5 a ceiling point at x = q is hidden when the ray crosses x = 0.5 at a height in
// [z0, z1]; that height is (0.5 - p) / (q - p). So the visible part of the ceiling is a union of x-ranges,
// known in closed form.
double wallReference(double z0, double z1) {
  auto visibleFrom = [&](const Vec3& x) {
    double p = x.x();
    const bool mirrored = p > 0.5;
    if (mirrored) p = 1 - p;
    const double d = 0.5 - p;
    // Hidden q range: q - p in [d / min(z1,1), d / max(z0,0)], i.e. q in [p + d / z1c, p + d / z0c].
    const double z1c = std::min(z1, 1.0), z0c = std::max(z0, 0.0);
    const double qLo = p + d / z1c;
    const double qHi = z0c > 0 ? p + d / z0c : 1e30;
    double total = 0;
    auto add = [&](double a, double b) {
      a = std::clamp(a, 0.0, 1.0);
      b = std::clamp(b, 0.0, 1.0);
      if (b <= a) return;
      const double lo = mirrored ? 1 - b : a, hi = mirrored ? 1 - a : b;
      total += pointToPolygonFormFactor(x, kUp, rectangleAtHeight(lo, hi, 0, 1, 1));
    };
    add(0, qLo);
    add(qHi, 1);
    return total;
  };
  const Polygon left{{0, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0}, {0, 1, 0}};
  const Polygon right{{0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 1, 0}};
  return referenceIntegral({left, right}, visibleFrom);
}

Polygon wall(double z0, double z1) {
  return {{0.5, -20, z0}, {0.5, 21, z0}, {0.5, 21, z1}, {0.5, -20, z1}};
}

TEST(Occlusion, OccluderTouchingTheSource) {
  const Mesh mesh = test::meshFromPolygons({kFloor, kCeiling, wall(0, 0.5)});
  const EntryResult entry = elementFormFactor(mesh, 0, 1, splitOptions());
  const double expected = wallReference(0, 0.5);
  EXPECT_NEAR(entry.value, expected, 1e-7 * expected);
  EXPECT_LT(expected, 0.19982489569838738);  // the unoccluded C-11 value
}

TEST(Occlusion, OccluderStraddlingTheSourcePlane) {
  // The part below the floor blocks nothing: same as the wall standing on the floor.
  const Mesh mesh = test::meshFromPolygons({kFloor, kCeiling, wall(-0.7, 0.5)});
  const double expected = wallReference(0, 0.5);
  EXPECT_NEAR(elementFormFactor(mesh, 0, 1, splitOptions()).value, expected, 1e-7 * expected);
}

TEST(Occlusion, OccluderStraddlingTheReceiverPlane) {
  // The part above the ceiling blocks nothing.
  const Mesh mesh = test::meshFromPolygons({kFloor, kCeiling, wall(0.4, 1.6)});
  const double expected = wallReference(0.4, 1.0);
  EXPECT_NEAR(elementFormFactor(mesh, 0, 1, splitOptions()).value, expected, 1e-7 * expected);
}

// A rectangle parallel to floor and ceiling at height h casts the rectangle scaled by 1/h about x on the
// ceiling.
double parallelOccluderReference(double x0, double x1, double y0, double y1, double h) {
  auto visible = [&](const Vec3& x) {
    const double full = pointToPolygonFormFactor(x, kUp, kCeiling);
    auto shadow = [&](double a, double p) { return p + (a - p) / h; };
    const double sx0 = std::clamp(shadow(x0, x.x()), 0.0, 1.0), sx1 = std::clamp(shadow(x1, x.x()), 0.0, 1.0);
    const double sy0 = std::clamp(shadow(y0, x.y()), 0.0, 1.0), sy1 = std::clamp(shadow(y1, x.y()), 0.0, 1.0);
    if (sx1 <= sx0 || sy1 <= sy0) return full;
    return full - pointToPolygonFormFactor(x, kUp, rectangleAtHeight(sx0, sx1, sy0, sy1, 1));
  };
  // Kinks where a shadow edge crosses a ceiling edge: x = (a - h c) / (1 - h) for occluder edge a, ceiling
  // edge c.
  std::vector<double> xs{0, 1}, ys{0, 1};
  for (double a : {x0, x1})
    for (double c : {0.0, 1.0}) xs.push_back((a - h * c) / (1 - h));
  for (double a : {y0, y1})
    for (double c : {0.0, 1.0}) ys.push_back((a - h * c) / (1 - h));
  auto cut = [](std::vector<double> v) {
    std::vector<double> out;
    for (double t : v)
      if (t >= 0 && t <= 1) out.push_back(t);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  xs = cut(xs);
  ys = cut(ys);
  std::vector<Polygon> pieces;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i)
    for (std::size_t j = 0; j + 1 < ys.size(); ++j)
      pieces.push_back(
          {{xs[i], ys[j], 0}, {xs[i + 1], ys[j], 0}, {xs[i + 1], ys[j + 1], 0}, {xs[i], ys[j + 1], 0}});
  return referenceIntegral(pieces, visible);
}

TEST(Occlusion, ParallelOccluderMatchesClosedFormShadow) {
  const Mesh mesh = test::meshFromPolygons({kFloor, kCeiling, rectangleAtHeight(0.2, 0.8, 0.25, 0.75, 0.5)});
  const double expected = parallelOccluderReference(0.2, 0.8, 0.25, 0.75, 0.5);
  EXPECT_NEAR(elementFormFactor(mesh, 0, 1, splitOptions()).value, expected, 1e-7 * expected);
}

TEST(Occlusion, SeveralOverlappingOccludersActAsTheirUnion) {
  // Three overlapping pieces whose union is the rectangle [0.2, 0.8] x [0.25, 0.75] at height 0.5.
  const Mesh mesh = test::meshFromPolygons({kFloor, kCeiling, rectangleAtHeight(0.2, 0.6, 0.25, 0.75, 0.5),
                                            rectangleAtHeight(0.4, 0.8, 0.25, 0.6, 0.5),
                                            rectangleAtHeight(0.5, 0.8, 0.5, 0.75, 0.5)});
  const double expected = parallelOccluderReference(0.2, 0.8, 0.25, 0.75, 0.5);
  const EntryResult entry = elementFormFactor(mesh, 0, 1, splitOptions());
  EXPECT_NEAR(entry.value, expected, 1e-7 * expected);
  EXPECT_GT(entry.splitEvaluations, 0);
}

TEST(Occlusion, OccluderMeshedIntoAdjacentElements) {
  // Shared edges between occluder elements project onto shared edges: the exact union has no cracks.
  std::vector<Polygon> polygons{kFloor, kCeiling};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j)
      polygons.push_back(
          rectangleAtHeight(0.2 + 0.2 * i, 0.4 + 0.2 * i, 0.25 + 0.25 * j, 0.5 + 0.25 * j, 0.5));
  const Mesh mesh = test::meshFromPolygons(polygons);
  const double expected = parallelOccluderReference(0.2, 0.8, 0.25, 0.75, 0.5);
  EXPECT_NEAR(elementFormFactor(mesh, 0, 1, splitOptions()).value, expected, 1e-7 * expected);
}

TEST(Occlusion, AdjacentOccluderElementsLeaveOneHole) {
  std::vector<Polygon> polygons{kFloor, kCeiling};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      polygons.push_back(rectangleAtHeight(0.4 + 0.1 * i, 0.5 + 0.1 * i, 0.4 + 0.1 * j, 0.5 + 0.1 * j, 0.5));
  const Mesh mesh = test::meshFromPolygons(polygons);
  const VisibleRegion region = visibleRegion(mesh, 0, Vec3(0.5, 0.5, 0), 1);
  EXPECT_EQ(region.occluderProjections.size(), 4u);
  ASSERT_EQ(region.visible.size(),
            1u);  // the ceiling minus one square hole [0.3, 0.7]^2: no cracks between pieces
  ASSERT_EQ(region.visible[0].holes.size(), 1u);
  EXPECT_NEAR(region.visible[0].area(), 1.0 - 0.16, 1e-14);
}

TEST(Occlusion, SplitAndExactBooleansAgree) {
  std::vector<Polygon> polygons{kFloor,
                                kCeiling,
                                rectangleAtHeight(0.2, 0.6, 0.25, 0.75, 0.5),
                                rectangleAtHeight(0.4, 0.8, 0.25, 0.6, 0.5),
                                wall(0.3, 0.8),
                                {{0.1, 0.2, 0.3}, {0.9, 0.1, 0.45}, {0.7, 0.8, 0.6}, {0.2, 0.7, 0.5}}};
  const Mesh mesh = test::meshFromPolygons(polygons, 2);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int compared = 0, partial = 0;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    if (mesh.elements[i].patch != 0) continue;
    for (std::size_t j = 0; j < mesh.size(); ++j) {
      if (mesh.elements[j].patch != 1) continue;
      const Polygon p = mesh.polygon(static_cast<int>(i));
      for (int k = 0; k < 6; ++k) {
        const double s = u(rng), t = u(rng);
        const Vec3 x = (1 - s) * (1 - t) * p[0] + s * (1 - t) * p[1] + s * t * p[2] + (1 - s) * t * p[3];
        const double exact =
            pointFormFactor(mesh, static_cast<int>(i), x, static_cast<int>(j), Booleans::Exact);
        const double split =
            pointFormFactor(mesh, static_cast<int>(i), x, static_cast<int>(j), Booleans::Split);
        EXPECT_NEAR(split, exact, 1e-13);
        const VisibleRegion region = visibleRegion(mesh, static_cast<int>(i), x, static_cast<int>(j));
        EXPECT_NEAR(region.formFactor, exact, 1e-13);
        if (exact > 0 && exact < region.unoccludedFormFactor - 1e-9) ++partial;
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 4 * 4 * 6);
  EXPECT_GT(partial, 20);
}

TEST(Occlusion, VisibleRegionPiecesAndFormFactorAgree) {
  const Mesh mesh = test::meshFromPolygons({kFloor, kCeiling, rectangleAtHeight(0.3, 0.5, 0.3, 0.5, 0.5)});
  const Vec3 x(0.4, 0.4, 0);
  const VisibleRegion region = visibleRegion(mesh, 0, x, 1);
  ASSERT_EQ(region.visible.size(), 1u);
  ASSERT_EQ(region.visible[0].holes.size(), 1u);
  // Shadow of [0.3, 0.5]^2 at h = 0.5 from (0.4, 0.4): [0.2, 0.6]^2, area 0.16.
  EXPECT_NEAR(region.visible[0].area(), 1.0 - 0.16, 1e-14);
  const double hole = pointToPolygonFormFactor(x, kUp, rectangleAtHeight(0.2, 0.6, 0.2, 0.6, 1));
  EXPECT_NEAR(region.formFactor, region.unoccludedFormFactor - hole, 1e-15);
}

}  // namespace
}  // namespace rt::exact
