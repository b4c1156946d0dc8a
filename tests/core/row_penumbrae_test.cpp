// RowPenumbrae: a block is ruled out of a pair only when no segment from the row's element to the other
// element meets it, checked by brute force (segments between grids of points, against the box by slabs),
// and it does rule out most pairs a shaft's boxes would let through.
#include "core/formfactor/row_penumbrae.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/box_solid.h"

namespace rt {
namespace {

bool segmentMeetsBox(const Vec3& p, const Vec3& q, const Vec3& lo, const Vec3& hi) {
  double t0 = 0, t1 = 1;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = q[axis] - p[axis];
    if (std::abs(d) < 1e-15) {
      if (p[axis] < lo[axis] || p[axis] > hi[axis]) return false;
      continue;
    }
    double a = (lo[axis] - p[axis]) / d, b = (hi[axis] - p[axis]) / d;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

std::vector<Vec3> grid(const std::vector<Vec3>& square, int n) {
  std::vector<Vec3> points;
  for (int s = 0; s <= n; ++s)
    for (int t = 0; t <= n; ++t) {
      const double u = static_cast<double>(s) / n, v = static_cast<double>(t) / n;
      points.push_back((1 - u) * (1 - v) * square[0] + u * (1 - v) * square[1] + u * v * square[2] +
                       (1 - u) * v * square[3]);
    }
  return points;
}

TEST(RowPenumbrae, RulesOutOnlyBlocksThatNoSegmentMeets) {
  const Vec3 lo{0.4, 0.4, 0}, hi{0.6, 0.6, 0.5};  // a block standing on the floor
  const Box block = box(lo, hi);
  RowPenumbrae regions(block.shapes, 1e-12);
  // The row's element on the ceiling, facing down; the others on the floor, facing up, all over it.
  const std::vector<Vec3> row{{0.7, 0.1, 1}, {0.7, 0.3, 1}, {0.9, 0.3, 1}, {0.9, 0.1, 1}};
  const std::vector<Vec3> rowPoints = grid(row, 6);
  int ruledOut = 0, meet = 0;
  for (int x = 0; x < 10; ++x)
    for (int y = 0; y < 10; ++y) {
      const double s = 0.1 * x, t = 0.1 * y;
      const std::vector<Vec3> other{{s, t, 0}, {s + 0.1, t, 0}, {s + 0.1, t + 0.1, 0}, {s, t + 0.1, 0}};
      const bool out = regions.rulesOut(7, row.data(), 4, 0, other.data(), 4, other[0], Vec3(0, 0, 1));
      bool anyMeets = false;
      for (const Vec3& p : grid(other, 6))
        for (const Vec3& q : rowPoints) anyMeets |= segmentMeetsBox(p, q, lo, hi);
      if (out) {
        ++ruledOut;
        EXPECT_FALSE(anyMeets) << "floor square at " << s << ", " << t;
      }
      meet += anyMeets;
    }
  EXPECT_GT(meet, 5);
  EXPECT_GT(ruledOut, 50);  // of the 100 - meet that could be
}

TEST(RowPenumbrae, NoRegionWhereTheBlockIsAsHighAsTheRowsElement) {
  // The row's element on the floor the block stands on, the other on the ceiling: the block's bottom
  // corners are no nearer the ceiling than the row's corners, so its region there would be unbounded.
  const Box block = box({0.4, 0.4, 0}, {0.6, 0.6, 0.5});
  RowPenumbrae regions(block.shapes, 1e-12);
  const std::vector<Vec3> row{{0.8, 0.8, 0}, {0.9, 0.8, 0}, {0.9, 0.9, 0}, {0.8, 0.9, 0}};
  const std::vector<Vec3> far{{5, 5, 1}, {5, 6, 1}, {6, 6, 1}, {6, 5, 1}};
  EXPECT_FALSE(regions.rulesOut(3, row.data(), 4, 0, far.data(), 4, far[0], Vec3(0, 0, -1)));
}

}  // namespace
}  // namespace rt
