// The JSON scene format: what loads, and that every rejection names the file, the line and the JSON path.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
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

// Expects `text` to be rejected with a message naming `location` (file:line at /path) and containing
// `phrase`.
void expectRejected(const std::string& text, const std::string& location, const std::string& phrase) {
  const std::string m = rejection(text);
  EXPECT_NE(m.find(location), std::string::npos) << "location '" << location << "' missing from: " << m;
  EXPECT_NE(m.find(phrase), std::string::npos) << "phrase '" << phrase << "' missing from: " << m;
}

const std::string kSourceSquare = "[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]";

std::string withSourcePolygon(const std::string& polygon) {
  return replaced(kTwoSquares, kSourceSquare, polygon);
}

TEST(SceneJson, RejectsReflectanceOfOne) {
  expectRejected(replaced(kTwoSquares, "[0.5, 0.5, 0.5]", "[0.5, 1.0, 0.5]"),
                 "bad.json:6 at /materials/1/reflectance", "outside [0,1)");
}

TEST(SceneJson, RejectsNegativeReflectance) {
  expectRejected(replaced(kTwoSquares, "[0.5, 0.5, 0.5]", "-0.1"), "bad.json:6 at /materials/1/reflectance",
                 "outside [0,1)");
}

TEST(SceneJson, RejectsNegativeEmission) {
  expectRejected(replaced(kTwoSquares, "\"emission\": [1, 1, 1]", "\"emission\": [1, -1, 1]"),
                 "bad.json:5 at /materials/0/emission", "negative");
}

TEST(SceneJson, RejectsInfiniteEmission) {
  expectRejected(replaced(kTwoSquares, "\"emission\": [1, 1, 1]", "\"emission\": [1, 1e999, 1]"),
                 "bad.json:5", "number overflow parsing '1e999'");
}

TEST(SceneJson, SceneWithoutLightLoadsButCannotBeSolved) {
  const Scene s = parseSceneJson(replaced(kTwoSquares, "\"emission\": [1, 1, 1]", "\"emission\": [0, 0, 0]"),
                                 "dark.json");
  EXPECT_EQ(s.patches.size(), 2u);
  try {
    requireLight(s);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dark.json: error: no light"), std::string::npos) << e.what();
  }
}

TEST(SceneJson, RejectsNaNAsSyntaxErrorWithLine) {
  // JSON has no NaN: the literal is a syntax error, reported at its line.
  expectRejected(withSourcePolygon("[[0, 0, 0], [1, NaN, 0], [1, 1, 0], [0, 1, 0]]"), "bad.json:10",
                 "JSON syntax error");
}

TEST(SceneJson, RejectsOverflowingCoordinateAtItsLine) {
  // nlohmann::json refuses numbers that overflow a double, so 1e999 never becomes infinity.
  expectRejected(withSourcePolygon("[[0, 0, 0], [1, 1e999, 0], [1, 1, 0], [0, 1, 0]]"), "bad.json:10",
                 "number overflow");
}

TEST(SceneJson, RejectsPolygonWithTwoVertices) {
  expectRejected(withSourcePolygon("[[0, 0, 0], [1, 0, 0]]"), "bad.json:10 at /surfaces/0/polygons/0",
                 "at least 3");
}

TEST(SceneJson, RejectsPolygonWithTwoDistinctVertices) {
  expectRejected(withSourcePolygon("[[0, 0, 0], [1, 0, 0], [1, 0, 0], [0, 0, 0]]"),
                 "bad.json:10 at /surfaces/0/polygons/0", "degenerate polygon");
}

TEST(SceneJson, RejectsCollinearPolygon) {
  expectRejected(withSourcePolygon("[[0, 0, 0], [1, 0, 0], [2, 0, 0]]"),
                 "bad.json:10 at /surfaces/0/polygons/0", "zero area");
}

TEST(SceneJson, SplitsNonConvexPolygonIntoTriangles) {
  // An L shape: ear clipping covers it with 4 triangles of its area 3.
  const Scene s = parseSceneJson(
      withSourcePolygon("[[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0]]"), "l.json");
  double area = 0;
  int pieces = 0;
  for (const Patch& p : s.patches)
    if (p.origin.jsonPath == "/surfaces/0/polygons/0") {
      area += p.area;
      ++pieces;
      EXPECT_TRUE(p.normal.isApprox(Vec3(0, 0, 1))) << p.normal.transpose();
    }
  EXPECT_EQ(pieces, 4);
  EXPECT_NEAR(area, 3.0, 1e-12);
  ASSERT_FALSE(s.warnings.empty());
  EXPECT_NE(s.warnings[0].find("l.json:10 at /surfaces/0/polygons/0: warning: polygon is not convex"),
            std::string::npos)
      << s.warnings[0];
}

TEST(SceneJson, RejectsBowTie) {
  expectRejected(withSourcePolygon("[[0, 0, 0], [3, 2, 0], [3, 0, 0], [0, 1, 0]]"),
                 "bad.json:10 at /surfaces/0/polygons/0",
                 "crosses itself: its edges between vertices 1-2 and 3-4");
  // A symmetric bow tie's two lobes cancel: no area at all.
  expectRejected(withSourcePolygon("[[0, 0, 0], [1, 1, 0], [1, 0, 0], [0, 1, 0]]"),
                 "bad.json:10 at /surfaces/0/polygons/0", "zero area");
}

TEST(SceneJson, RejectsPentagramThatWindsTwice) {
  // Every turn has the same sign, but the outline goes around twice.
  expectRejected(withSourcePolygon("[[1, 0, 0], [-0.809017, 0.587785, 0], [0.309017, -0.951057, 0], "
                                   "[0.309017, 0.951057, 0], [-0.809017, -0.587785, 0]]"),
                 "bad.json:10 at /surfaces/0/polygons/0", "crosses itself");
}

TEST(SceneJson, SplitsNonPlanarQuadWithWarning) {
  const Scene s =
      parseSceneJson(withSourcePolygon("[[0, 0, 0], [1, 0, 0], [1, 1, 0.01], [0, 1, 0]]"), "warp.json");
  ASSERT_EQ(s.patches.size(), 3u);  // two triangles + the receiver
  EXPECT_EQ(s.patches[0].vertices.size(), 3u);
  EXPECT_EQ(s.patches[1].vertices.size(), 3u);
  EXPECT_NEAR(s.patches[0].area + s.patches[1].area, 1.0, 1e-4);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("warp.json:10 at /surfaces/0/polygons/0"), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("not planar"), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("0.01 m from the plane of the first three"), std::string::npos)
      << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("split into 2 triangles"), std::string::npos) << s.warnings[0];
}

TEST(SceneJson, KeepsPlanarQuadWithinToleranceWhole) {
  // 1e-8 out of plane on a unit square is below the 1e-6 relative tolerance.
  const Scene s = parseSceneJson(withSourcePolygon("[[0, 0, 0], [1, 0, 0], [1, 1, 1e-8], [0, 1, 0]]"));
  EXPECT_EQ(s.patches.size(), 2u);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(SceneJson, DropsRepeatedClosingVertexWithWarning) {
  const Scene s =
      parseSceneJson(withSourcePolygon("[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 0]]"));
  EXPECT_EQ(s.patches[0].vertices.size(), 4u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("repeated vertex"), std::string::npos) << s.warnings[0];
}

TEST(SceneJson, RejectsUnknownMaterial) {
  expectRejected(replaced(kTwoSquares, "\"material\": \"white\"", "\"material\": \"whit\""),
                 "bad.json:12 at /surfaces/1/material", "unknown material 'whit'");
}

TEST(SceneJson, RejectsDuplicateMaterial) {
  expectRejected(replaced(kTwoSquares, "\"name\": \"white\"", "\"name\": \"light\""),
                 "bad.json:6 at /materials/1/name", "duplicate material name");
}

TEST(SceneJson, RejectsMisspeltKey) {
  expectRejected(replaced(kTwoSquares, "\"reflectance\": [0.5", "\"reflectence\": [0.5"),
                 "bad.json:6 at /materials/1/reflectence", "unknown key \"reflectence\"");
}

TEST(SceneJson, RejectsRepeatedKey) {
  expectRejected(replaced(kTwoSquares, "\"reflectance\": [0.5, 0.5, 0.5]",
                          "\"reflectance\": [0.5, 0.5, 0.5],\n \"reflectance\": [0.1, 0.1, 0.1]"),
                 "bad.json:7 at /materials/1/reflectance", "appears twice");
}

TEST(SceneJson, AcceptsWindowsLineEndings) {
  std::string text;
  for (const char c : kTwoSquares) text += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const Scene s = parseSceneJson(text);
  EXPECT_EQ(s.patches[1].origin.line, 13);
}

TEST(SceneJson, RejectsMissingKey) {
  expectRejected(replaced(kTwoSquares, "\"material\": \"white\", ", ""), "bad.json:12 at /surfaces/1",
                 "missing required key \"material\"");
}

TEST(SceneJson, RejectsWrongTypes) {
  expectRejected(replaced(kTwoSquares, "[[0, 0, 1], [0, 1, 1]", "[[0, 0, 1], [0, 1]"),
                 "bad.json:13 at /surfaces/1/polygons/0/1", "expected [x, y, z]");
  expectRejected(replaced(kTwoSquares, "\"unit\": \"m\"", "\"unit\": 3"), "bad.json:3 at /unit",
                 "expected a string");
  expectRejected("[1, 2]", "bad.json", "expected an object");
}

TEST(SceneJson, RejectsBadCamera) {
  const std::string camera =
      "\"unit\": \"m\",\n  \"camera\": {\"position\": [0, 0, 5], \"target\": [0, 0, 0], ";
  expectRejected(replaced(kTwoSquares, "\"unit\": \"m\",", camera + "\"fov_y_degrees\": 200},"),
                 "bad.json:4 at /camera/fov_y_degrees", "outside (0, 180)");
  expectRejected(replaced(kTwoSquares, "\"unit\": \"m\",", camera + "\"up\": [0, 0, 1]},"),
                 "bad.json:4 at /camera/up", "parallel");
}

TEST(SceneJson, ReadsCameraAndGreyShorthand) {
  std::string text = replaced(kTwoSquares, "\"unit\": \"m\",",
                              "\"unit\": \"m\", \"camera\": {\"position\": [0, 0, 5], \"target\": [0, 0, 0], "
                              "\"fov_y_degrees\": 30},");
  text = replaced(text, "[0.5, 0.5, 0.5]", "0.25");
  const Scene s = parseSceneJson(text);
  ASSERT_TRUE(s.camera.has_value());
  EXPECT_TRUE(s.camera->position.isApprox(Vec3(0, 0, 5)));
  EXPECT_TRUE(s.camera->up.isApprox(Vec3(0, 1, 0)));
  EXPECT_DOUBLE_EQ(s.camera->fovYDegrees, 30);
  EXPECT_TRUE((s.materials[1].reflectance == Rgb::Constant(0.25)).all());
}

TEST(SceneJson, RejectsMissingFileAndUnknownExtension) {
  try {
    loadScene("/nonexistent/scene.json");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.json: error: cannot open"), std::string::npos)
        << e.what();
  }
  try {
    loadScene("scene.stl");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.stl: error: unknown scene format '.stl'"), std::string::npos)
        << e.what();
  }
}

TEST(SceneJson, PlanarityToleranceIsRelativeToThePolygonsSize) {
  // 1e-4 out of plane is planar for a 500-unit quad (2e-7 of its size) but not for a unit one (1e-4).
  const Scene big =
      parseSceneJson(withSourcePolygon("[[0, 0, 0], [500, 0, 0], [500, 500, 0.0001], [0, 500, 0]]"));
  EXPECT_TRUE(big.warnings.empty());
  const Scene small = parseSceneJson(withSourcePolygon("[[0, 0, 0], [1, 0, 0], [1, 1, 0.0001], [0, 1, 0]]"));
  EXPECT_EQ(small.warnings.size(), 1u);
}

TEST(SceneJson, TheDocumentedExampleLoads) {
  std::ifstream in(test::sourcePath("docs/scene-format.md"));
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::size_t begin = doc.find("```json\n");
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = doc.find("```", begin + 8);
  const Scene s = parseSceneJson(doc.substr(begin + 8, end - begin - 8), "scene-format.md");
  EXPECT_EQ(s.patches.size(), 2u);
  EXPECT_TRUE(s.camera.has_value());
  EXPECT_TRUE((s.materials[1].reflectance == Rgb::Constant(0.5)).all());
}

TEST(SceneJson, EveryTruncationIsAnInputErrorNeverACrash) {
  for (std::size_t length = 0; length < kTwoSquares.size(); ++length) {
    try {
      parseSceneJson(kTwoSquares.substr(0, length), "cut.json");
      ADD_FAILURE() << "a scene cut after " << length << " characters loaded";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, "cut.json");
    }
  }
}

TEST(SceneJson, CorruptedBytesGiveInputErrorsOnly) {
  // Every position overwritten by characters that matter to JSON: the result loads or is an InputError.
  int loaded = 0;
  for (std::size_t at = 0; at < kTwoSquares.size(); ++at) {
    for (const char c : std::string("]}\",-0e9x")) {
      std::string text = kTwoSquares;
      text[at] = c;
      try {
        parseSceneJson(text, "bad.json");
        ++loaded;
      } catch (const InputError&) {
      }
    }
  }
  EXPECT_GT(loaded, 0);  // e.g. a digit changed inside a coordinate
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
