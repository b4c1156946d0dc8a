// OBJ/MTL files as modelling tools and model archives write them: inline comments, texture maps, vertex
// normals and texture coordinates, faces without a material, n-gons (convex, concave, non-planar).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/io/mtl_reader.h"
#include "core/io/scene_loader.h"
#include "core/mesh.h"
#include "support/test_paths.h"

namespace rt {
namespace {

int countContaining(const std::vector<std::string>& lines, const std::string& phrase) {
  int n = 0;
  for (const std::string& line : lines) n += line.find(phrase) != std::string::npos ? 1 : 0;
  return n;
}

TEST(SceneObjArchive, CornellBoxAsAnArchivePublishesItLoads) {
  const Scene s = loadScene(test::dataPath("obj/cornell-archive.obj"));
  EXPECT_EQ(s.patches.size(), 16u);  // 5 walls, 2 x 5 box faces, the light
  EXPECT_EQ(s.surfaces.size(), 8u);
  ASSERT_EQ(s.materials.size(), 8u);
  for (const Material& m : s.materials) {
    if (m.name == "leftWall") {
      EXPECT_TRUE(m.reflectance.isApprox(Rgb(0.63, 0.065, 0.05))) << "inline # Red";
    }
    if (m.name == "light") {
      EXPECT_TRUE(m.emission.isApprox(Rgb(17, 12, 4)));
    } else {
      EXPECT_FALSE(m.isEmitter()) << m.name;
    }
  }
  // Two materials carry texture maps (the floor two of them): one warning each; nothing else to say.
  EXPECT_EQ(countContaining(s.warnings, "(a texture) is ignored"), 2) << ::testing::PrintToString(s.warnings);
  EXPECT_EQ(countContaining(s.warnings, "cornell-archive.mtl:13: warning: material 'backWall': map_Kd"), 1);
  EXPECT_EQ(s.warnings.size(), 2u) << ::testing::PrintToString(s.warnings);
  // Every patch faces into the box (y up, open front at z = +1).
  for (const Patch& p : s.patches) {
    const Vec3 toCentre = Vec3(0, 1, 0) - p.vertices[0];
    if (s.surfaces[p.surface].name.find("Box") == std::string::npos) {
      EXPECT_GT(p.normal.dot(toCentre), 0) << s.surfaces[p.surface].name;
    }
  }
}

TEST(SceneObjArchive, MtlInlineCommentsTextureMapsAndUnknownStatements) {
  const io_detail::MtlLibrary library = io_detail::parseMtl(
      "newmtl a # first\nKd 0.5 0.25 0.125 # brownish\nmap_Kd a.png\nmap_Kd b.png\nmap_Ks c.png\n"
      "newmtl b\nKd 0.2\nKe 3 # grey light\nfrobnicate 1\nfrobnicate 2\n",
      "lib.mtl");
  ASSERT_EQ(library.materials.size(), 2u);
  EXPECT_EQ(library.materials[0].material.name, "a");
  EXPECT_TRUE(library.materials[0].material.reflectance.isApprox(Rgb(0.5, 0.25, 0.125)));
  EXPECT_TRUE((library.materials[1].material.emission == Rgb::Constant(3)).all());
  ASSERT_EQ(library.warnings.size(), 2u) << ::testing::PrintToString(library.warnings);
  EXPECT_NE(library.warnings[0].find("lib.mtl:3: warning: material 'a': map_Kd"), std::string::npos);
  EXPECT_NE(library.warnings[1].find("lib.mtl:9: warning: unknown statement 'frobnicate'"),
            std::string::npos);
}

TEST(SceneObjArchive, MtlValuesAreCheckedAtTheirLine) {
  for (const auto& [text, phrase] : std::vector<std::pair<std::string, std::string>>{
           {"newmtl a\nKd 1 1 1\n", "lib.mtl:2: error: material 'a': reflectance [1, 1, 1] is outside [0,1)"},
           {"newmtl a\nKd 0.5\nKe -1 0 0\n",
            "lib.mtl:3: error: material 'a': emission [-1, 0, 0] is negative"},
           {"newmtl a\nKd nan 0 0\n",
            "lib.mtl:2: error: material 'a': reflectance [nan, 0, 0] is not a finite"},
           {"Kd 0.5\n", "lib.mtl:1: error: Kd before any 'newmtl <name>'"},
           {"newmtl\n", "lib.mtl:1: error: newmtl needs a material name"}}) {
    try {
      io_detail::parseMtl(text, "lib.mtl");
      ADD_FAILURE() << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
    }
  }
}

const std::string kRoomMtl = "newmtl white\nKd 0.5\nnewmtl lamp\nKd 0.1\nKe 10\n";

// A lamp (square, facing up) under faces the test writes; faces before 'usemtl' get the default material.
Scene loadRoom(const std::string& faces) {
  const std::string obj = "mtllib room.mtl\n" + faces +
                          "v 0.4 0.4 -1\nv 0.6 0.4 -1\nv 0.6 0.6 -1\nv 0.4 0.6 -1\n"
                          "usemtl lamp # the light\nf -4 -3 -2 -1 # facing +z\n";
  return parseSceneObj(obj, "dir/room.obj", [](const std::string& path) -> std::optional<std::string> {
    if (path == "dir/room.mtl") return kRoomMtl;
    return std::nullopt;
  });
}

TEST(SceneObjArchive, FacesBeforeAnyUsemtlGetTheDefaultMaterialOnce) {
  const Scene s = loadRoom("v 0 0 0\nv 0 1 0\nv 1 1 0\nv 1 0 0\nf 1 2 3 4\nf 4 3 2 1 # back to back\n");
  ASSERT_EQ(s.patches.size(), 3u);
  EXPECT_EQ(s.materialOfPatch(0).name, "default");
  ASSERT_EQ(countContaining(s.warnings, "face before any 'usemtl'"), 1)
      << ::testing::PrintToString(s.warnings);
  EXPECT_EQ(countContaining(s.warnings, "dir/room.obj:6: warning: face before any 'usemtl'"), 1);
  EXPECT_EQ(countContaining(s.warnings, "as do the 1 other such faces"), 1);
}

TEST(SceneObjArchive, ConvexPentagonStaysOneElementWithoutSubdivision) {
  const Scene s = loadRoom(
      "usemtl white\nv 0 0 0\nv 0 1 0\nv 0.8 1.3 0\nv 1.2 0.5 0\nv 0.8 -0.2 0\nf 1 2 3 4 5 # a convex "
      "pentagon\n");
  ASSERT_EQ(s.patches.size(), 2u);
  EXPECT_EQ(s.patches[0].vertices.size(), 5u);
  EXPECT_TRUE(s.warnings.empty()) << ::testing::PrintToString(s.warnings);
  const Mesh whole = buildMesh(s, {});
  ASSERT_EQ(whole.size(), 2u);
  EXPECT_EQ(whole.elements[0].vertices.size(), 5u);
  EXPECT_NEAR(whole.elements[0].area, s.patches[0].area, 1e-12);
  MeshOptions fine;
  fine.mode = MeshOptions::Mode::MaxEdge;
  fine.maxEdge = 0.3;
  const Mesh split = buildMesh(s, fine);
  double area = 0;
  for (const Element& e : split.elements)
    if (e.patch == 0) {
      EXPECT_EQ(e.vertices.size(), 3u);
      area += e.area;
    }
  EXPECT_NEAR(area, s.patches[0].area, 1e-12);
}

TEST(SceneObjArchive, ConcaveAndNonPlanarNgonsAreTriangulatedWithAWarning) {
  // An L, and the same L with one corner lifted out of its plane.
  const std::string lShape =
      "usemtl white\nv 0 0 0\nv 0 2 0\nv 1 2 0\nv 1 1 0\nv 2 1 0\nv 2 0 0\nf 1 2 3 4 5 6\n";
  const Scene flat = loadRoom(lShape);
  ASSERT_EQ(flat.patches.size(), 5u);
  double area = 0;
  for (std::size_t i = 0; i + 1 < flat.patches.size(); ++i) area += flat.patches[i].area;
  EXPECT_NEAR(area, 3.0, 1e-12);
  ASSERT_EQ(flat.warnings.size(), 1u);
  EXPECT_NE(
      flat.warnings[0].find("room.obj:9: warning: polygon is not convex (6 vertices); split into 4 triangles "
                            "by ear clipping"),
      std::string::npos)
      << flat.warnings[0];
  const Scene lifted = loadRoom(std::string(lShape).replace(lShape.find("v 1 1 0"), 7, "v 1 1 0.1"));
  ASSERT_EQ(lifted.warnings.size(), 1u);
  EXPECT_NE(lifted.warnings[0].find("polygon is not convex (6 vertices) and is not planar"),
            std::string::npos)
      << lifted.warnings[0];
}

TEST(SceneObjArchive, SelfIntersectingFaceIsAnErrorNamingTheEdges) {
  try {
    loadRoom("usemtl white\nv 0 0 0\nv 3 2 0\nv 3 0 0\nv 0 1 0\nf 1 2 3 4\n");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("room.obj:7: error: polygon outline crosses itself"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rt
