// Exact segment visibility (CGAL AABB tree, exact predicates) against a plain floating-point ray caster on
// the same points: they must agree except where a segment passes within a stated distance of a triangle edge
// (grazing), where rounding decides the floating answer. Also: V(x, y) agrees with the exact visible region
// from x.
#include <gtest/gtest.h>

#include <random>

#include "core/polygon.h"
#include "exact/exact_reference.h"
#include "exact/exact_scenes.h"

namespace rt::exact {
namespace {

// Moller-Trumbore in double precision, open segment (t in (eps, 1 - eps)): the kind of test a fast ray caster
// uses.
bool floatingHit(const Vec3& x, const Vec3& y, const Polygon& t) {
  const Vec3 d = y - x;
  const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
  const Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-14) return false;
  const Vec3 s = x - t[0];
  const double u = s.dot(p) / det;
  if (u < 0 || u > 1) return false;
  const Vec3 q = s.cross(e1);
  const double v = d.dot(q) / det;
  if (v < 0 || u + v > 1) return false;
  const double hit = e2.dot(q) / det;
  return hit > 1e-9 && hit < 1 - 1e-9;
}

bool floatingVisible(const Mesh& mesh, const Vec3& x, const Vec3& y, int a, int b) {
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    if (static_cast<int>(e) == a || static_cast<int>(e) == b) continue;
    for (const Polygon& t : fanTriangulate(mesh.polygon(static_cast<int>(e))))
      if (floatingHit(x, y, t)) return false;
  }
  return true;
}

double segmentSegmentDistance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  // Sampled minimum is enough for a tolerance check at the 1e-6 level on unit scenes.
  double best = INFINITY;
  const Vec3 u = p1 - p0, v = q1 - q0;
  const Vec3 w = p0 - q0;
  const double a = u.dot(u), b = u.dot(v), c = v.dot(v), d = u.dot(w), e = v.dot(w);
  const double den = a * c - b * b;
  double s = den > 1e-300 ? std::clamp((b * e - c * d) / den, 0.0, 1.0) : 0.0;
  double t = c > 0 ? std::clamp((b * s + e) / c, 0.0, 1.0) : 0.0;
  s = a > 0 ? std::clamp((b * t - d) / a, 0.0, 1.0) : 0.0;
  best = std::min(best, (p0 + s * u - (q0 + t * v)).norm());
  return best;
}

// Distance from the segment to the nearest triangle edge in the mesh (other than the end elements').
double grazingDistance(const Mesh& mesh, const Vec3& x, const Vec3& y, int a, int b) {
  double best = INFINITY;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    if (static_cast<int>(e) == a || static_cast<int>(e) == b) continue;
    for (const Polygon& t : fanTriangulate(mesh.polygon(static_cast<int>(e))))
      for (int k = 0; k < 3; ++k) best = std::min(best, segmentSegmentDistance(x, y, t[k], t[(k + 1) % 3]));
  }
  return best;
}

Vec3 randomPointOn(const Polygon& quad, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.02, 0.98);
  const double s = u(rng), t = u(rng);
  return (1 - s) * (1 - t) * quad[0] + s * (1 - t) * quad[1] + s * t * quad[2] + (1 - s) * t * quad[3];
}

Mesh roomWithBoxes() {
  std::vector<Polygon> polygons = test::roomFaces({0, 0, 0}, {1, 1, 1});
  for (const Polygon& f : test::boxFaces({0.2, 0.0, 0.2}, {0.5, 0.45, 0.5}, false)) polygons.push_back(f);
  for (const Polygon& f : test::boxFaces({0.55, 0.2, 0.5}, {0.8, 0.6, 0.75}, true)) polygons.push_back(f);
  return test::meshFromPolygons(polygons, 2);
}

TEST(SegmentVisibility, AgreesWithFloatingRayCasterExceptWhenGrazing) {
  const Mesh mesh = roomWithBoxes();
  const SegmentVisibility exact(mesh);
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(mesh.size()) - 1);
  const double grazingEpsilon = 1e-9;
  int blocked = 0, disagreements = 0, checked = 0;
  for (int sample = 0; sample < 4000; ++sample) {
    const int a = pick(rng), b = pick(rng);
    if (a == b) continue;
    const Vec3 x = randomPointOn(mesh.polygon(a), rng), y = randomPointOn(mesh.polygon(b), rng);
    const bool v = exact.visible(x, y, a, b);
    const bool f = floatingVisible(mesh, x, y, a, b);
    ++checked;
    if (!v) ++blocked;
    if (v != f) {
      ++disagreements;
      EXPECT_LT(grazingDistance(mesh, x, y, a, b), grazingEpsilon) << "sample " << sample;
    }
  }
  EXPECT_GT(checked, 3500);
  EXPECT_GT(blocked, 300);  // the boxes do block a good share
  EXPECT_LE(disagreements, 2);
}

TEST(SegmentVisibility, ThroughASharedEdgeIsBlocked) {
  // Two occluder elements sharing the edge x = 0.5 at height 0.5; a segment crossing exactly that edge is
  // blocked (the union of closed triangles has no crack), and so is one through the shared corner of four
  // elements.
  std::vector<Polygon> polygons{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}},
                                {{0.0, 0, 0.5}, {0.0, 1, 0.5}, {1.0, 1, 0.5}, {1.0, 0, 0.5}}};
  const Mesh mesh =
      test::meshFromPolygons(polygons, 2);  // occluder split 2 x 2: edges at x = 0.5 and y = 0.5
  const SegmentVisibility exact(mesh);
  int floorElement = -1, ceilingElement = -1;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& element = mesh.elements[e];
    if (element.patch == 0 && element.centroid.x() < 0.5 && element.centroid.y() < 0.5)
      floorElement = static_cast<int>(e);
    if (element.patch == 1 && element.centroid.x() > 0.5 && element.centroid.y() > 0.5)
      ceilingElement = static_cast<int>(e);
  }
  EXPECT_FALSE(exact.visible(Vec3(0.25, 0.3, 0), Vec3(0.75, 0.7, 1), floorElement, ceilingElement));
  EXPECT_FALSE(exact.visible(Vec3(0.25, 0.25, 0), Vec3(0.75, 0.75, 1), floorElement, ceilingElement));
  EXPECT_EQ(exact.blockers(Vec3(0.25, 0.25, 0), Vec3(0.75, 0.75, 1), floorElement, ceilingElement).size(),
            4u);
  // Touching only at an end point (here the occluder's shared corner) does not block.
  EXPECT_TRUE(exact.visible(Vec3(0.25, 0.25, 0), Vec3(0.5, 0.5, 0.5), floorElement, -1));
}

TEST(SegmentVisibility, AgreesWithTheExactVisibleRegion) {
  const Mesh mesh = roomWithBoxes();
  const SegmentVisibility exact(mesh);
  std::mt19937_64 rng(11);
  int source = -1, receiver = -1;
  // The floor element under the first box (points in its footprint see nothing) and the ceiling element above
  // the second box.
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& el = mesh.elements[e];
    const bool low = el.centroid.x() < 0.5 && el.centroid.z() < 0.5;
    const bool high = el.centroid.x() > 0.5 && el.centroid.z() > 0.5;
    if (el.normal.y() > 0.5 && el.centroid.y() < 1e-9 && low) source = static_cast<int>(e);
    if (el.normal.y() < -0.5 && high) receiver = static_cast<int>(e);
  }
  ASSERT_GE(source, 0);
  ASSERT_GE(receiver, 0);
  int inside = 0, outside = 0;
  for (int k = 0; k < 30; ++k) {
    const Vec3 x = randomPointOn(mesh.polygon(source), rng);
    const VisibleRegion region = visibleRegion(mesh, source, x, receiver);
    for (int m = 0; m < 30; ++m) {
      const Vec3 y = randomPointOn(mesh.polygon(receiver), rng);
      // Point-in-region in the receiver's plane: winding of outer minus holes, via projected angles.
      auto contains = [&](const Polygon& polygon) {
        const Vec3 n = mesh.elements[receiver].normal;
        double winding = 0;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
          const Vec3 a = polygon[i] - y, b = polygon[(i + 1) % polygon.size()] - y;
          winding += std::atan2(n.dot(a.cross(b)), a.dot(b));
        }
        return std::abs(winding) > 3;
      };
      bool in = false;
      for (const PolygonWithHoles& piece : region.visible) {
        bool here = contains(piece.outer);
        for (const Polygon& hole : piece.holes) here = here && !contains(hole);
        in = in || here;
      }
      EXPECT_EQ(in, exact.visible(x, y, source, receiver));
      (in ? inside : outside) += 1;
    }
  }
  EXPECT_GT(inside, 0);
  EXPECT_GT(outside, 0);
}

}  // namespace
}  // namespace rt::exact
