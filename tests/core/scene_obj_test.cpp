// Wavefront OBJ/MTL scenes: faces become patches, groups surfaces, Kd/Ke materials; every rejection names
// file:line.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/io/scene_loader.h"
#include "support/test_paths.h"

namespace rt {
namespace {

const std::string kObj = R"(# unit: cm
# name: two squares
# camera: position 0.5 0.5 5 target 0.5 0.5 0 up 0 1 0 fov_y_degrees 30
mtllib two.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 0 1 1
v 1 1 1
v 1 0 1
g source
usemtl light
f 1 2 3 4
g receiver
usemtl white
f 5/1/1 6/2/1 7/3/1 8/4/1
)";

const std::string kMtl = R"(newmtl light
Kd 0 0 0
Ke 1 2 3

newmtl white
Kd 0.5 0.25 0.125
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Writes two.obj and two.mtl into a fresh folder named after the test; returns the .obj path.
std::string writeScene(const std::string& obj, const std::string& mtl) {
  const std::string dir = test::scratchDir(std::string("scene_obj_") +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::ofstream(dir + "/two.obj") << obj;
  std::ofstream(dir + "/two.mtl") << mtl;
  return dir + "/two.obj";
}

void expectRejected(const std::string& obj, const std::string& mtl, const std::string& location,
                    const std::string& phrase) {
  const std::string path = writeScene(obj, mtl);
  try {
    loadSceneObj(path);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(location), std::string::npos) << "location '" << location << "' missing from: " << m;
    EXPECT_NE(m.find(phrase), std::string::npos) << "phrase '" << phrase << "' missing from: " << m;
  }
}

TEST(SceneObj, LoadsFacesGroupsMaterialsAndComments) {
  const std::string path = writeScene(kObj, kMtl);
  const Scene s = loadScene(path);
  EXPECT_EQ(s.name, "two squares");
  EXPECT_EQ(s.unit, "cm");
  ASSERT_TRUE(s.camera.has_value());
  EXPECT_TRUE(s.camera->position.isApprox(Vec3(0.5, 0.5, 5)));
  EXPECT_DOUBLE_EQ(s.camera->fovYDegrees, 30);
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].name, "light");
  EXPECT_TRUE(s.materials[0].emission.isApprox(Rgb(1, 2, 3)));
  EXPECT_TRUE(s.materials[1].reflectance.isApprox(Rgb(0.5, 0.25, 0.125)));
  EXPECT_FALSE(s.materials[1].isEmitter());
  ASSERT_EQ(s.surfaces.size(), 2u);
  EXPECT_EQ(s.surfaces[0].name, "source");
  EXPECT_EQ(s.surfaces[1].name, "receiver");
  EXPECT_EQ(s.surfaces[1].material, 1);
  ASSERT_EQ(s.patches.size(), 2u);
  EXPECT_TRUE(s.patches[0].normal.isApprox(Vec3(0, 0, 1)));
  EXPECT_TRUE(s.patches[1].normal.isApprox(Vec3(0, 0, -1)));
  EXPECT_DOUBLE_EQ(s.patches[1].area, 1.0);
  EXPECT_EQ(s.patches[1].origin.file, path);
  EXPECT_EQ(s.patches[1].origin.line, 18);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(SceneObj, GroupWithTwoMaterialsBecomesTwoSurfaces) {
  std::string obj = replaced(kObj, "g receiver\n", "");
  const Scene s = loadSceneObj(writeScene(obj, kMtl));
  ASSERT_EQ(s.surfaces.size(), 2u);
  EXPECT_EQ(s.surfaces[0].name, "source/light");
  EXPECT_EQ(s.surfaces[1].name, "source/white");
}

TEST(SceneObj, SingleValueKdIsGrey) {
  const Scene s = loadSceneObj(writeScene(kObj, replaced(kMtl, "Kd 0.5 0.25 0.125", "Kd 0.5")));
  EXPECT_TRUE((s.materials[1].reflectance == Rgb::Constant(0.5)).all());
}

TEST(SceneObj, RejectsReflectanceOfOneAtTheKdLine) {
  expectRejected(kObj, replaced(kMtl, "Kd 0.5 0.25 0.125", "Kd 1.0 0.25 0.125"), "two.mtl:6",
                 "outside [0,1)");
}

TEST(SceneObj, RejectsNegativeEmissionAtTheKeLine) {
  expectRejected(kObj, replaced(kMtl, "Ke 1 2 3", "Ke 1 -2 3"), "two.mtl:3", "negative");
}

TEST(SceneObj, RejectsMalformedKd) {
  expectRejected(kObj, replaced(kMtl, "Kd 0.5 0.25 0.125", "Kd 0.5 0.25"), "two.mtl:6",
                 "needs 1 or 3 numbers");
  expectRejected(kObj, replaced(kMtl, "Kd 0.5 0.25 0.125", "Kd 0.5 x 0.1"), "two.mtl:6",
                 "'x' is not a number");
}

TEST(SceneObj, RejectsMaterialWithoutKd) {
  expectRejected(kObj, replaced(kMtl, "Kd 0.5 0.25 0.125\n", ""), "two.mtl:5", "has no Kd");
}

TEST(SceneObj, RejectsUnknownMaterialAtTheUsemtlLine) {
  expectRejected(replaced(kObj, "usemtl white", "usemtl whit"), kMtl, "two.obj:17",
                 "unknown material 'whit'");
}

TEST(SceneObj, FaceWithoutMaterialGetsTheDefaultWithAWarning) {
  // The source face (line 14 once its usemtl is gone) comes before any usemtl; the receiver's white follows.
  const Scene s =
      loadSceneObj(writeScene(replaced(kObj, "usemtl light\n", ""),
                              replaced(kMtl, "Kd 0.5 0.25 0.125", "Kd 0.5 0.25 0.125\nKe 1 1 1")));
  ASSERT_EQ(s.patches.size(), 2u);
  const Material& m = s.materialOfPatch(0);
  EXPECT_EQ(m.name, "default");
  EXPECT_TRUE((m.reflectance == Rgb::Constant(0.5)).all());
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("two.obj:14: warning: face before any 'usemtl'"), std::string::npos)
      << s.warnings[0];
}

TEST(SceneObj, RejectsMissingMaterialLibrary) {
  expectRejected(replaced(kObj, "mtllib two.mtl", "mtllib none.mtl"), kMtl, "two.obj:4",
                 "cannot open the material library");
}

TEST(SceneObj, RejectsVertexIndexOutOfRange) {
  expectRejected(replaced(kObj, "f 1 2 3 4", "f 1 2 3 40"), kMtl, "two.obj:15", "out of range");
  expectRejected(replaced(kObj, "f 1 2 3 4", "f 1 2 3 0"), kMtl, "two.obj:15", "out of range");
  expectRejected(replaced(kObj, "f 1 2 3 4", "f 1 2 3 -9"), kMtl, "two.obj:15", "out of range");
}

TEST(SceneObj, AcceptsNegativeIndices) {
  const Scene s =
      loadSceneObj(writeScene(replaced(kObj, "f 5/1/1 6/2/1 7/3/1 8/4/1", "f -4 -3 -2 -1"), kMtl));
  EXPECT_TRUE(s.patches[1].normal.isApprox(Vec3(0, 0, -1)));
}

TEST(SceneObj, RejectsFaceWithTwoVertices) {
  expectRejected(replaced(kObj, "f 1 2 3 4", "f 1 2"), kMtl, "two.obj:15", "at least 3");
}

TEST(SceneObj, RejectsNaNAndMalformedVertices) {
  expectRejected(replaced(kObj, "v 1 1 0\n", "v 1 nan 0\n"), kMtl, "two.obj:7", "not a finite number");
  expectRejected(replaced(kObj, "v 1 1 0\n", "v 1 inf 0\n"), kMtl, "two.obj:7", "not a finite number");
  expectRejected(replaced(kObj, "v 1 1 0\n", "v 1 1,0 0\n"), kMtl, "two.obj:7", "malformed vertex");
  expectRejected(replaced(kObj, "v 1 1 0\n", "v 1 1\n"), kMtl, "two.obj:7", "malformed vertex");
}

TEST(SceneObj, RejectsDegenerateFaces) {
  expectRejected(replaced(kObj, "f 1 2 3 4", "f 1 2 2 1"), kMtl, "two.obj:15", "degenerate polygon");
  expectRejected(replaced(kObj, "f 1 2 3 4", "f 1 3 2 4"), kMtl, "two.obj:15", "zero area");
}

TEST(SceneObj, SplitsConcaveFaceByEarClippingWithWarning) {
  // 0,0 1,0 0.2,0.2 0,1: a dart, concave at the third vertex.
  const Scene s = loadSceneObj(writeScene(replaced(kObj, "v 1 1 0\n", "v 0.2 0.2 0\n"), kMtl));
  ASSERT_EQ(s.patches.size(), 3u);
  EXPECT_NEAR(s.patches[0].area + s.patches[1].area, 0.2, 1e-12);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("two.obj:15: warning: polygon is not convex"), std::string::npos)
      << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("split into 2 triangles by ear clipping"), std::string::npos) << s.warnings[0];
}

TEST(SceneObj, SplitsNonPlanarFaceWithWarning) {
  const Scene s = loadSceneObj(writeScene(replaced(kObj, "v 1 1 0\n", "v 1 1 0.05\n"), kMtl));
  EXPECT_EQ(s.patches.size(), 3u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("two.obj:15: warning: polygon is not planar"), std::string::npos)
      << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("0.0499 cm from the plane of the first three"), std::string::npos)
      << s.warnings[0];
}

TEST(SceneObj, SceneWithoutLightLoadsButCannotBeSolved) {
  // Form factors need no light, so the file loads; a solve asks for one and names the file.
  const Scene s = loadSceneObj(writeScene(kObj, replaced(kMtl, "Ke 1 2 3", "Ke 0 0 0")));
  try {
    requireLight(s);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("two.obj: error: no light"), std::string::npos) << e.what();
  }
}

TEST(SceneObj, RejectsMissingFile) {
  try {
    loadScene("/nonexistent/box.obj");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/box.obj: error: cannot open"), std::string::npos)
        << e.what();
  }
}

TEST(SceneObj, TruncatedAndCorruptedFilesGiveInputErrorsOnly) {
  std::string obj, mtl;
  int loaded = 0;
  auto attempt = [&](const std::string& objText, const std::string& mtlText) {
    try {
      loadSceneObj(writeScene(objText, mtlText));
      ++loaded;
    } catch (const InputError&) {
    }
  };
  for (std::size_t length = 0; length <= kObj.size(); length += 7) attempt(kObj.substr(0, length), kMtl);
  for (std::size_t length = 0; length <= kMtl.size(); length += 3) attempt(kObj, kMtl.substr(0, length));
  for (std::size_t at = 0; at < kObj.size(); at += 3) {
    std::string text = kObj;
    text[at] = at % 2 ? '-' : '/';
    attempt(text, kMtl);
  }
  EXPECT_GT(loaded, 0);
}

TEST(SceneObj, RejectsBadCameraComment) {
  expectRejected(replaced(kObj, "fov_y_degrees 30", "fov_y_degrees"), kMtl, "two.obj:3", "camera: ");
}

}  // namespace
}  // namespace rt
