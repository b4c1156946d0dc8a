// The exact method's shaft with the element index (a box tree, built once per mesh) finds the same occluders,
// in the same order, as the scan over every element that it replaces for whole matrices.
#include <gtest/gtest.h>

#include "exact/exact_scenes.h"
#include "exact/shaft.h"

namespace rt::exact {
namespace {

// A closed unit room (faces inward) with a block standing on its floor (faces outward, no bottom), each
// polygon split 3 x 3: shafts with and without occluders, touching boxes, coplanar neighbours.
std::vector<Polygon> roomWithBlock() {
  std::vector<Polygon> p{
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},  // floor, +z
      {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}},  // ceiling, -z
      {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}},  // y = 0, +y
      {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}},  // y = 1, -y
      {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}},  // x = 0, +x
      {{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}},  // x = 1, -x
  };
  const double a = 0.3, b = 0.7, h = 0.4;
  p.push_back({{a, a, h}, {b, a, h}, {b, b, h}, {a, b, h}});  // block top, +z
  p.push_back({{a, a, 0}, {b, a, 0}, {b, a, h}, {a, a, h}});  // y = a, -y
  p.push_back({{b, b, 0}, {a, b, 0}, {a, b, h}, {b, b, h}});  // y = b, +y
  p.push_back({{a, b, 0}, {a, a, 0}, {a, a, h}, {a, b, h}});  // x = a, -x
  p.push_back({{b, a, 0}, {b, b, 0}, {b, b, h}, {b, a, h}});  // x = b, +x
  return p;
}

TEST(ShaftIndex, FindsTheSameOccludersAsTheScanOverEveryElement) {
  const Mesh mesh = test::meshFromPolygons(roomWithBlock(), 3);
  const ElementIndex index(mesh);
  int occluded = 0;
  for (int i = 0; i < static_cast<int>(mesh.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(mesh.size()); ++j) {
      const PairGeometry scanned = setUpPair(mesh, i, j);
      const PairGeometry indexed = setUpPair(mesh, i, j, true, &index);
      ASSERT_EQ(scanned.facing, indexed.facing) << i << ", " << j;
      ASSERT_EQ(scanned.occluders, indexed.occluders) << i << ", " << j;
      occluded += !scanned.occluders.empty();
    }
  EXPECT_GT(occluded, 100);  // the block stands between many pairs
}

}  // namespace
}  // namespace rt::exact
