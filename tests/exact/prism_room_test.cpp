// The exact reference on scenes/prism-room.json, one element per polygon: a row of the downward disc sums to
// 1 (the room is closed) whichever element of each pair the entry is computed from, as the matrix computes it
// from the one of lower index.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/io/scene_loader.h"
#include "exact/exact_reference.h"
#include "support/test_paths.h"

namespace rt::exact {
namespace {

// The pair from the wall at y = 0 (element 4) to a fan triangle of the downward disc (element 185) has the
// prism between them. Its source must be cut along every visibility event that matters: in a cell still
// crossed by one, a sliver of what the prism takes away can fall between all the cubature points, and the
// entry comes out short with an error estimate of nearly 0. The crease edges of the prism make events only in
// its face planes, which keeps the cut below its cap of cells.
TEST(ExactPrismRoom, ADiscRowSumsToOneFromEitherSideOfEachPair) {
  const Scene scene = loadScene(rt::test::sourcePath("scenes/prism-room.json"));
  const Mesh mesh = buildMesh(scene, MeshOptions{});
  constexpr int kDisc = 185;
  ASSERT_EQ(mesh.size(), 191u);
  ASSERT_EQ(scene
                .surfaces[static_cast<std::size_t>(
                    scene.patches[static_cast<std::size_t>(mesh.elements[kDisc].patch)].surface)]
                .name,
            "disc_bottom");
  const ExactOptions options = exactOptionsFor(1e-9);  // the command line's default
  const double area = mesh.elements[kDisc].area;
  double row = 0, worst = 0;
  int worstAt = -1;
  for (int j = 0; j < static_cast<int>(mesh.size()); ++j) {
    const double forward = elementFormFactor(mesh, kDisc, j, options).value;
    const double backward = elementFormFactor(mesh, j, kDisc, options).value * mesh.elements[j].area / area;
    row += j < kDisc ? backward : forward;
    const double gap = std::abs(forward - backward);
    if (gap > worst) worst = gap, worstAt = j;
  }
  EXPECT_NEAR(row, 1.0, 1e-6);
  EXPECT_LE(worst, 1e-7) << "largest difference between the two directions at element " << worstAt;
}

}  // namespace
}  // namespace rt::exact
