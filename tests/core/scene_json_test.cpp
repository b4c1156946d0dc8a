// The JSON scene format: what loads, and that every rejection names the file, the line and the JSON path.
#include <gtest/gtest.h>

#include <string>

#include "core/io/scene_loader.h"
#include "support/test_paths.h"

namespace rt {
namespace {

// A valid one-light scene; tests edit a copy of it to produce each error.
const std::string kTwoSquares = R"({
  "name": "two squares",
  "unit": "m",
  "materials": [
    {"name": "light", "reflectance": [0, 0, 0], "emission": [1, 1, 1]},
    {"name": "white", "reflectance": [0.5, 0.5, 0.5]}
  ],
  "surfaces": [
    {"name": "source", "material": "light", "polygons": [
      [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
    ]},
    {"name": "receiver", "material": "white", "polygons": [
      [[0, 0, 1], [0, 1, 1], [1, 1, 1], [1, 0, 1]]
    ]}
  ]
})";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Parses `text` expecting an InputError; returns its full message ("file:line at /path: error: ...").
std::string rejection(const std::string& text, const std::string& fileName = "bad.json") {
  try {
    parseSceneJson(text, fileName);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError for:\n" << text;
  return {};
}

TEST(SceneJson, ParsesMaterialsSurfacesAndPatches) {
  const Scene s = parseSceneJson(kTwoSquares, "two.json");
  EXPECT_EQ(s.name, "two squares");
  EXPECT_EQ(s.unit, "m");
  EXPECT_EQ(s.sourceFile, "two.json");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_TRUE(s.materials[0].isEmitter());
  EXPECT_FALSE(s.materials[1].isEmitter());
  ASSERT_EQ(s.surfaces.size(), 2u);
  EXPECT_EQ(s.surfaces[1].name, "receiver");
  EXPECT_EQ(s.surfaces[1].material, 1);
  ASSERT_EQ(s.patches.size(), 2u);
  EXPECT_DOUBLE_EQ(s.patches[0].area, 1.0);
  EXPECT_TRUE(s.patches[0].normal.isApprox(Vec3(0, 0, 1)));
  EXPECT_TRUE(s.patches[1].normal.isApprox(Vec3(0, 0, -1)));
  EXPECT_EQ(s.patches[1].origin.file, "two.json");
  EXPECT_EQ(s.patches[1].origin.jsonPath, "/surfaces/1/polygons/0");
  EXPECT_EQ(s.patches[1].origin.line, 13);
  EXPECT_TRUE(s.warnings.empty());
  EXPECT_FALSE(s.camera.has_value());
}

TEST(SceneJson, RejectsReflectanceOfOne) {
  const std::string m = rejection(replaced(kTwoSquares, "[0.5, 0.5, 0.5]", "[0.5, 1.0, 0.5]"));
  EXPECT_NE(m.find("bad.json:6 at /materials/1/reflectance"), std::string::npos) << m;
  EXPECT_NE(m.find("outside [0,1)"), std::string::npos) << m;
}

TEST(SceneJson, RejectsSceneWithoutLight) {
  const std::string m =
      rejection(replaced(kTwoSquares, "\"emission\": [1, 1, 1]", "\"emission\": [0, 0, 0]"));
  EXPECT_NE(m.find("bad.json"), std::string::npos) << m;
  EXPECT_NE(m.find("no light"), std::string::npos) << m;
}

TEST(SceneJson, SyntaxErrorNamesLineAndColumn) {
  const std::string m = rejection(replaced(kTwoSquares, "\"unit\": \"m\",", "\"unit\": \"m\""));
  EXPECT_NE(m.find("bad.json:4"), std::string::npos) << m;
  EXPECT_NE(m.find("JSON syntax error at column"), std::string::npos) << m;
}

TEST(SceneJson, LoadsCornellBoxWithSplitLeftWall) {
  const std::string path = test::sourcePath("scenes/cornell-box.json");
  const Scene s = loadScene(path);
  EXPECT_EQ(s.unit, "mm");
  // light, floor, 4 ceiling pieces, back, 2 left-wall triangles, right, 5 + 5 block faces.
  EXPECT_EQ(s.patches.size(), 20u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("cornell-box.json:"), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("/surfaces/4/polygons/0"), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("not planar"), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("3.2"), std::string::npos) << s.warnings[0];
}

}  // namespace
}  // namespace rt
