#include "exact/discontinuity_triangulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/io/scene_loader.h"
#include "core/refine/refine.h"
#include "core/scene.h"
#include "support/test_paths.h"

namespace rt::exact {
namespace {

double twiceArea(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// True when the segment p-q is a union of triangle edges: every point along it lies on an edge of the
// triangulation.
bool isCoveredByEdges(const PlanarTriangulation& t, const Vec2& p, const Vec2& q) {
  for (double s = 0.01; s < 1; s += 0.02) {
    const Vec2 x = p + s * (q - p);
    bool onEdge = false;
    for (const auto& tri : t.triangles)
      for (int k = 0; k < 3 && !onEdge; ++k) {
        const Vec2 a = t.points[tri[k]], b = t.points[tri[(k + 1) % 3]];
        const double len = (b - a).norm();
        const double along = (x - a).dot(b - a) / (len * len);
        onEdge = along >= -1e-9 && along <= 1 + 1e-9 && std::abs(twiceArea(a, b, x)) <= 1e-9 * len;
      }
    if (!onEdge) return false;
  }
  return true;
}

TEST(DiscontinuityTriangulation, ConstraintsBecomeEdgesAndAreaIsKept) {
  PlanarDomain d;
  d.boundary = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  d.constraints = {
      {{1, 0.5}, {1, 3.5}}, {{0.5, 2.2}, {3.5, 2.2}}, {{0.3, 0.3}, {3.7, 3.1}}};  // crossing lines
  d.maxEdge = 0.8;
  const PlanarTriangulation t = triangulateWithConstraints(d);
  ASSERT_FALSE(t.triangles.empty());
  double area = 0;
  for (const auto& tri : t.triangles) {
    const double a2 = twiceArea(t.points[tri[0]], t.points[tri[1]], t.points[tri[2]]);
    EXPECT_GT(a2, 0);
    area += a2 / 2;
    for (int k = 0; k < 3; ++k) EXPECT_LE((t.points[tri[k]] - t.points[tri[(k + 1) % 3]]).norm(), 0.8 + 1e-9);
  }
  EXPECT_NEAR(area, 16.0, 1e-9);
  for (const auto& [p, q] : d.constraints) EXPECT_TRUE(isCoveredByEdges(t, p, q));
}

TEST(DiscontinuityTriangulation, DiscontinuityMeshOfTheShadowSceneFollowsTheUmbra) {
  registerDiscontinuityTriangulation();
  EXPECT_EQ(constrainedTriangulatorName(), "CGAL constrained Delaunay");
  // Square light over square occluder over floor: the umbra on the floor is |x|, |y| <= 0.75.
  Scene s;
  s.materials = {{"light", Rgb::Zero(), Rgb::Constant(100)}, {"grey", Rgb::Constant(0.5), Rgb::Zero()}};
  s.surfaces = {{"light", 0}, {"grey", 1}};
  auto add = [&](double z, double h, int surface, bool up) {
    Patch p;
    p.vertices = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}};
    if (!up) std::swap(p.vertices[1], p.vertices[3]);
    p.normal = Vec3(0, 0, up ? 1 : -1);
    p.area = 4 * h * h;
    p.surface = surface;
    s.patches.push_back(p);
  };
  add(2, 0.25, 0, false);
  add(1, 0.5, 1, true);
  add(0, 2, 1, true);
  RefineOptions o;
  o.mode = RefineMode::Discontinuity;
  o.initialMaxEdge = 0.5;
  const RefinedSolution r = solveRefined(s, o);
  EXPECT_TRUE(r.tVertices.empty());  // a conforming triangulation per patch
  for (std::size_t e = 0; e < r.mesh.size(); ++e) {
    if (r.mesh.elements[e].patch != 2) continue;
    double lo = 1e9, hi = -1e9, ylo = 1e9, yhi = -1e9;
    for (const Vec3& v : r.mesh.polygon(static_cast<int>(e))) {
      lo = std::min(lo, v.x()), hi = std::max(hi, v.x());
      ylo = std::min(ylo, v.y()), yhi = std::max(yhi, v.y());
    }
    if (ylo > -0.75 && yhi < 0.75) {
      EXPECT_FALSE(lo < 0.75 - 1e-6 && hi > 0.75 + 1e-6) << "element " << e;
    }
  }
  EXPECT_LT(radiosityAt(r, 2, Vec3(0, 0, 0))[0], 0.05 * radiosityAt(r, 2, Vec3(1.8, 0, 0))[0]);
}

}  // namespace
}  // namespace rt::exact

namespace rt::exact {
namespace {

// Cornell box numbers for docs/benchmarks.md; disabled by default (a minute or two). Run with
//   exact_tests --gtest_also_run_disabled_tests --gtest_filter='DiscontinuityTriangulation.DISABLED_*'
TEST(DiscontinuityTriangulation, DISABLED_CornellBox) {
  registerDiscontinuityTriangulation();
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
  RefineOptions ref;
  ref.mode = RefineMode::Uniform;
  ref.initialMaxEdge = 30;
  const RefinedSolution reference = solveRefined(scene, ref);
  for (double edge : {193.0, 100.0, 65.0}) {
    RefineOptions o;
    o.mode = RefineMode::Discontinuity;
    o.initialMaxEdge = edge;
    const RefinedSolution s = solveRefined(scene, o);
    std::printf("| discontinuity (CGAL), %.0f mm | %zu | %zu | %.2f | %.3f | %.3f |\n   %s\n", edge,
                s.stats.elements, s.stats.pairsComputed, s.stats.seconds, relativeRmsError(s, reference),
                relativeRmsError(s, reference, true), s.stats.summary().c_str());
  }
}

}  // namespace
}  // namespace rt::exact
