// BlockShadowRegion and its two caches: a block is said to miss a pair only when no segment between the two
// elements meets it, and to hide all only when every segment does, checked by brute force (segments between
// grids of points, against the box by slabs); and both verdicts are given for most pairs that have one.
#include "core/formfactor/quadrature/block_shadow_regions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/box_solid.h"

namespace rt {
namespace {

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

// How many of the segments between the two squares' grids meet the box: none, some or all.
enum class Seen { None, Some, All };
Seen segmentsMeeting(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const Vec3& lo, const Vec3& hi) {
  int meet = 0, total = 0;
  for (const Vec3& p : grid(a, 6))
    for (const Vec3& q : grid(b, 6)) {
      meet += segmentMeetsBox(p, q, lo, hi);
      ++total;
    }
  return meet == 0 ? Seen::None : meet == total ? Seen::All : Seen::Some;
}

std::vector<Vec3> floorSquare(double s, double t, double size) {
  return {{s, t, 0}, {s + size, t, 0}, {s + size, t + size, 0}, {s, t + size, 0}};
}

const Vec3 kLo{0.4, 0.4, 0}, kHi{0.6, 0.6, 0.5};  // a block standing on the floor, z = 0

TEST(BlockShadowRegions, ARowsVerdictsHoldForEverySegment) {
  const Box block = box(kLo, kHi);
  RowShadowRegions regions(block.shapes, 1e-12);
  // The row's element on the ceiling, facing down; the others on the floor all over the block.
  const std::vector<Vec3> row{{0.3, 0.3, 1}, {0.3, 0.4, 1}, {0.4, 0.4, 1}, {0.4, 0.3, 1}};
  int misses = 0, hides = 0;
  for (int x = 0; x < 20; ++x)
    for (int y = 0; y < 20; ++y) {
      const std::vector<Vec3> other = floorSquare(0.05 * x, 0.05 * y, 0.05);
      const BlockVerdict verdict =
          regions.judge(7, row.data(), 4, 0, other.data(), 4, other[0], Vec3(0, 0, 1));
      const Seen seen = segmentsMeeting(row, other, kLo, kHi);
      if (verdict == BlockVerdict::Misses) {
        ++misses;
        EXPECT_EQ(seen, Seen::None) << x << ", " << y;
      }
      if (verdict == BlockVerdict::HidesAll) {
        ++hides;
        EXPECT_EQ(seen, Seen::All) << x << ", " << y;
      }
    }
  EXPECT_GT(misses, 200);
  EXPECT_GT(hides, 5);
}

TEST(BlockShadowRegions, ElementsOnTheFloorTheBlockStandsOn) {
  const Box block = box(kLo, kHi);
  // Elements 0..399 on the floor (facing up), 400 on the ceiling (facing down).
  std::vector<std::vector<Vec3>> polygons;
  std::vector<Vec3> normals;
  for (int x = 0; x < 20; ++x)
    for (int y = 0; y < 20; ++y) {
      polygons.push_back(floorSquare(0.05 * x, 0.05 * y, 0.05));
      normals.emplace_back(0, 0, 1);
    }
  polygons.push_back({{0.7, 0.65, 1}, {0.7, 0.75, 1}, {0.8, 0.75, 1}, {0.8, 0.65, 1}});
  normals.emplace_back(0, 0, -1);
  const ContactShadowRegions contact(block.shapes, static_cast<int>(polygons.size()), polygons, normals,
                                     1e-12);
  ASSERT_TRUE(contact.any());
  // From the ceiling's side, the region on the floor is unbounded: the block stands there.
  RowShadowRegions rows(block.shapes, 1e-12);
  EXPECT_EQ(
      rows.judge(0, polygons[0].data(), 4, 0, polygons[400].data(), 4, polygons[400][0], Vec3(0, 0, -1)),
      BlockVerdict::Unknown);
  int misses = 0, hides = 0;
  for (int e = 0; e < 400; ++e) {
    const BlockVerdict verdict = contact.judge(0, e, polygons[static_cast<std::size_t>(e)].data(), 4, 400);
    const Seen seen = segmentsMeeting(polygons[static_cast<std::size_t>(e)], polygons[400], kLo, kHi);
    if (verdict == BlockVerdict::Misses) {
      ++misses;
      EXPECT_EQ(seen, Seen::None) << e;
    }
    if (verdict == BlockVerdict::HidesAll) {
      ++hides;
      EXPECT_EQ(seen, Seen::All) << e;
    }
  }
  EXPECT_GT(misses, 200);
  EXPECT_GT(hides, 3);
  // Not on the contact plane: no verdict.
  EXPECT_EQ(contact.judge(0, 400, polygons[400].data(), 4, 0), BlockVerdict::Unknown);
}

}  // namespace
}  // namespace rt
