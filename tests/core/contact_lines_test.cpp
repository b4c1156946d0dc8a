// Contact lines: the Cornell box's blocks stand on the floor, and the mesh chosen when no mesh option is
// given cuts the floor along their footprints, so that no floor element is partly under a block. The cut
// keeps the floor's area and its orientation, and a patch that nothing stands on is left as it is.
#include <gtest/gtest.h>

#include "core/contact_lines.h"
#include "core/io/scene_loader.h"
#include "core/mesh.h"
#include "core/polygon.h"
#include "formfactor_scenes.h"
#include "support/test_paths.h"

namespace rt {
namespace {

using test::patchOf;

// The block's footprint on the floor: its top's corners dropped to y = 0, as (x, z).
std::vector<Vec2> footprint(const Scene& scene, const std::string& block) {
  std::vector<Vec2> out;
  for (const Patch& p : scene.patches)
    if (scene.surfaces[static_cast<std::size_t>(p.surface)].name == block && p.normal.y() > 0.99)
      for (const Vec3& v : p.vertices) out.emplace_back(v.x(), v.z());
  return out;
}

// +1 strictly inside the convex outline, -1 strictly outside, 0 on it (within tolerance).
int side(const std::vector<Vec2>& outline, const Vec2& point, double tolerance) {
  bool onEdge = false;
  int sign = 0;
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const Vec2 a = outline[k], b = outline[(k + 1) % outline.size()];
    const Vec2 e = b - a, d = point - a;
    const double cross = (e.x() * d.y() - e.y() * d.x()) / e.norm();
    if (std::abs(cross) <= tolerance) {
      onEdge = true;
      continue;
    }
    const int s = cross > 0 ? 1 : -1;
    if (sign != 0 && s != sign) return -1;
    sign = s;
  }
  return onEdge ? 0 : 1;
}

TEST(ContactLines, TheDefaultMeshCutsTheFloorAlongBothBlocksFootprints) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
  const int floor = patchOf(scene, "floor");
  ASSERT_GE(floor, 0);
  // Four sides of each block stand on the floor.
  EXPECT_EQ(contactSegments(scene, floor, 1e-4).size(), 8u);
  const std::vector<Polygon> pieces = cutAtContacts(scene, floor, 1e-4);
  double area = 0;
  for (const Polygon& piece : pieces) {
    area += polygonArea(piece);
    EXPECT_TRUE(isConvex(piece, scene.patches[static_cast<std::size_t>(floor)].normal));
    EXPECT_GT(newellNormal(piece).normalized().dot(scene.patches[static_cast<std::size_t>(floor)].normal),
              0.999);
  }
  EXPECT_NEAR(area, scene.patches[static_cast<std::size_t>(floor)].area, 1e-6 * area);

  const MeshOptions options = defaultMeshOptions(scene);
  EXPECT_TRUE(options.splitAtContacts);
  const Mesh mesh = buildMesh(scene, options);
  int straddling = 0, under = 0;
  for (const char* block : {"short_block", "tall_block"}) {
    const std::vector<Vec2> outline = footprint(scene, block);
    ASSERT_EQ(outline.size(), 4u);
    for (const Element& e : mesh.elements) {
      if (e.patch != floor) continue;
      bool in = false, out = false;
      for (int v : e.vertices) {
        const int s = side(outline, Vec2(mesh.vertices[v].x(), mesh.vertices[v].z()), 1e-3);
        in = in || s > 0;
        out = out || s < 0;
      }
      straddling += in && out;
      under += in && !out;
    }
  }
  EXPECT_EQ(straddling, 0);
  EXPECT_GT(under, 0);  // the floor under the blocks is still there (it sees nothing)
}

TEST(ContactLines, AWallMeetingTheFloorAtItsEdgeCutsNothing) {
  const Scene scene = loadScene(test::sourcePath("scenes/furnace-cube.json"));
  for (std::size_t p = 0; p < scene.patches.size(); ++p) {
    EXPECT_TRUE(contactSegments(scene, static_cast<int>(p), 1e-9).empty()) << p;
    EXPECT_EQ(cutAtContacts(scene, static_cast<int>(p), 1e-9).size(), 1u) << p;
  }
}

TEST(ContactLines, ExplicitMeshOptionsKeepThePlainGrid) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
  MeshOptions plain;
  plain.mode = MeshOptions::Mode::MaxEdge;
  plain.maxEdge = 100;
  MeshOptions cut = plain;
  cut.splitAtContacts = true;
  const Mesh a = buildMesh(scene, plain), b = buildMesh(scene, cut);
  EXPECT_GT(b.size(), a.size());
  EXPECT_NEAR(b.areas().sum(), a.areas().sum(), 1e-9 * a.areas().sum());
}

}  // namespace
}  // namespace rt
