// The proof that two blocks never hide the same part of a pair (shadow_overlap.h), checked against every
// segment between grids on the two elements, and the separating-plane search it rests on.
#include "core/formfactor/quadrature/shadow_overlap.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/box_solid.h"

namespace rt {
namespace {

// Whether some segment between grids of points on two quadrilaterals meets both boxes.
bool someSegmentMeetsBoth(const ConvexPolygon& a, const ConvexPolygon& b, const Box& first, const Box& second,
                          int steps) {
  auto at = [](const ConvexPolygon& q, double s, double t) {
    return Vec3((1 - s) * ((1 - t) * q.v[0] + t * q.v[3]) + s * ((1 - t) * q.v[1] + t * q.v[2]));
  };
  auto meets = [](const Vec3& p, const Vec3& q, const Box& box) {
    Vec3 lo = box.shapes[0].corners[0], hi = lo;
    for (const Vec3& c : box.shapes[0].corners) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
    return segmentMeetsBox(p, q, lo, hi);
  };
  for (int s = 0; s <= steps; ++s)
    for (int t = 0; t <= steps; ++t)
      for (int u = 0; u <= steps; ++u)
        for (int v = 0; v <= steps; ++v) {
          const Vec3 p = at(a, double(s) / steps, double(t) / steps),
                     q = at(b, double(u) / steps, double(v) / steps);
          if (meets(p, q, first) && meets(p, q, second)) return true;
        }
  return false;
}

bool apart(const ConvexPolygon& source, const ConvexPolygon& receiver, const Box& a, const Box& b) {
  const ConvexPolygon* elements[2] = {&source, &receiver};
  const SolidShape* solids[2] = {&a.shapes[0], &b.shapes[0]};
  return shadowsApartBy([&](int e, int near, int other) {
    return solidOutsideHullOfSolidAndPolygon(*solids[other], *solids[near], elements[e]->v.data(),
                                             elements[e]->count, 1e-12);
  });
}

TEST(ShadowsApart, OnlyWhereNoSegmentMeetsBothBlocks) {
  // Two blocks on the floor of a unit room, one tall and one low, apart along x; floor elements and
  // elements of the wall x = 0 (facing +x) and of the wall y = 1 (facing -y).
  const Box low = box({0.15, 0.4, 0}, {0.35, 0.6, 0.3}), tall = box({0.6, 0.3, 0}, {0.8, 0.5, 0.6});
  std::vector<ConvexPolygon> floor, walls;
  for (double x = 0.05; x < 1; x += 0.2)
    for (double y = 0.05; y < 1; y += 0.2) {
      const bool underLow = x + 0.1 > 0.15 && x < 0.35 && y + 0.1 > 0.4 && y < 0.6;
      const bool underTall = x + 0.1 > 0.6 && x < 0.8 && y + 0.1 > 0.3 && y < 0.5;
      if (!underLow && !underTall)
        floor.push_back(polygon({{x, y, 0}, {x + 0.1, y, 0}, {x + 0.1, y + 0.1, 0}, {x, y + 0.1, 0}}));
    }
  for (double u = 0.05; u < 1; u += 0.2)
    for (double z : {0.05, 0.25, 0.5, 0.8}) {
      walls.push_back(polygon({{0, u, z}, {0, u + 0.1, z}, {0, u + 0.1, z + 0.1}, {0, u, z + 0.1}}));
      walls.push_back(polygon({{u, 1, z}, {u, 1, z + 0.1}, {u + 0.1, 1, z + 0.1}, {u + 0.1, 1, z}}));
    }
  int proven = 0, meeting = 0;
  for (const ConvexPolygon& f : floor)
    for (const ConvexPolygon& w : walls) {
      const bool both = someSegmentMeetsBoth(f, w, low, tall, 4);
      meeting += both;
      EXPECT_EQ(apart(f, w, low, tall), apart(w, f, tall, low));  // the same proof either way round
      if (!apart(f, w, low, tall)) continue;
      ++proven;
      EXPECT_FALSE(both) << "floor at " << f.v[0].transpose() << ", wall at " << w.v[0].transpose();
    }
  // Measured: of 840 pairs, 24 have segments through both blocks and 792 are proven apart.
  EXPECT_GT(proven, 750);
  EXPECT_GT(meeting, 20);
}

TEST(ShadowsApart, TouchingBlocksAreNeverProvenApart) {
  const Box a = box({0.2, 0.2, 0}, {0.5, 0.5, 0.5}), touching = box({0.5, 0.2, 0}, {0.8, 0.5, 0.3});
  const ConvexPolygon floor = polygon({{0, 0.8, 0}, {0.1, 0.8, 0}, {0.1, 0.9, 0}, {0, 0.9, 0}});
  const ConvexPolygon wall = polygon({{1, 0.3, 0.1}, {1, 0.3, 0.2}, {1, 0.4, 0.2}, {1, 0.4, 0.1}});
  EXPECT_FALSE(apart(floor, wall, a, touching));
}

TEST(HullsSeparated, ByAPlaneAlongAnEdgeOfEach) {
  // Two thin tetrahedra crossed like an X seen from above, one over the other: no face plane of either
  // separates them, only a plane along an edge of each.
  const std::vector<Vec3> p{{-1, 0, 0}, {1, 0, 0}, {0, 0.01, -0.01}, {0, -0.01, -0.01}};
  const std::vector<Vec3> q{{0, -1, 0.1}, {0, 1, 0.1}, {0.01, 0, 0.11}, {-0.01, 0, 0.11}};
  std::vector<std::pair<int, int>> edges;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) edges.push_back({i, j});
  EXPECT_TRUE(hullsSeparated(p.data(), 4, edges, q.data(), 4, edges, {}, 1e-9));
  std::vector<Vec3> crossing = q;
  for (Vec3& c : crossing) c.z() -= 0.1;  // now the two edges cross
  EXPECT_FALSE(hullsSeparated(p.data(), 4, edges, crossing.data(), 4, edges, {}, 1e-9));
}

}  // namespace
}  // namespace rt
