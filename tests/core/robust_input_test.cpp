// Bad input of every class gets an InputError naming the file and the line, JSON path or value, never a
// crash or a silent success. docs/robustness.md lists each class with its message and points here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "core/formfactor/formfactor_matrix.h"
#include "core/io/scene_assembly.h"
#include "core/io/scene_loader.h"
#include "core/mesh.h"
#include "support/test_paths.h"

namespace rt {
namespace {

// The message of the InputError `load` throws, or a test failure.
template <typename Load>
std::string inputError(Load&& load) {
  try {
    load();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

#define EXPECT_CONTAINS(text, phrase) EXPECT_NE((text).find(phrase), std::string::npos) << (text)

std::string writeFile(const std::string& name, const std::string& bytes) {
  const std::string path = test::scratchDir("robust_input") + "/" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(RobustInput, BinaryAndEmptyFilesAreInputErrors) {
  std::mt19937 random(7);
  std::string noise(4096, '\0');
  for (char& c : noise) c = static_cast<char>(random());
  for (const char* name : {"noise.obj", "noise.json"}) {
    const std::string path = writeFile(name, noise);
    EXPECT_CONTAINS(inputError([&] { loadScene(path); }), path + ":");
  }
  EXPECT_CONTAINS(inputError([&] { loadScene(writeFile("empty.obj", "")); }), "no faces");
  EXPECT_CONTAINS(inputError([&] { loadScene(writeFile("empty.json", "")); }), "empty.json:1");
  EXPECT_CONTAINS(inputError([] { loadScene("/nonexistent/room.json"); }),
                  "/nonexistent/room.json: error: cannot open");
}

TEST(RobustInput, TruncatedJsonNamesTheLine) {
  std::ifstream in(test::sourcePath("scenes/parallel-squares.json"));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string cut = text.substr(0, text.size() / 2);
  EXPECT_CONTAINS(inputError([&] { parseSceneJson(cut, "cut.json"); }), "cut.json:");
}

TEST(RobustInput, PolygonWithTooManyVerticesIsRefused) {
  std::string polygon = "[";
  for (int k = 0; k < 1001; ++k) {
    const double a = 6.283185307179586 * k / 1001;
    polygon += (k ? ", [" : "[") + std::to_string(std::cos(a)) + ", " + std::to_string(std::sin(a)) + ", 0]";
  }
  polygon += "]";
  const std::string scene =
      R"({"materials": [{"name": "l", "reflectance": [0.5, 0.5, 0.5], "emission": [1, 1, 1]}],
    "surfaces": [{"name": "disk", "material": "l", "polygons": [)" +
      polygon + "]}]}";
  EXPECT_CONTAINS(inputError([&] { parseSceneJson(scene, "disk.json"); }), "at most 1000 are accepted");
}

TEST(RobustInput, LightFacingAwayFromEverythingIsAWarning) {
  // The parallel squares with the light's vertex order reversed: it faces away from the receiver.
  std::ifstream in(test::sourcePath("scenes/parallel-squares.json"));
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const Scene normal = parseSceneJson(text, "squares.json");
  EXPECT_TRUE(normal.warnings.empty()) << ::testing::PrintToString(normal.warnings);
  Scene flipped = normal;
  for (Patch& p : flipped.patches)
    if (flipped.materialOf(p).isEmitter()) {
      std::reverse(p.vertices.begin(), p.vertices.end());
      p.normal = -p.normal;
    }
  io_detail::addLightWarnings(flipped);
  ASSERT_EQ(flipped.warnings.size(), 2u) << ::testing::PrintToString(flipped.warnings);
  EXPECT_CONTAINS(flipped.warnings[0], "faces away from every other surface: its emission reaches nothing");
  EXPECT_CONTAINS(flipped.warnings[1], "warning: no light reaches any surface");
}

TEST(RobustInput, AbsurdMeshSizeIsRefusedBeforeMeshingWithTheNumbers) {
  const Scene box = loadScene(test::sourcePath("scenes/cornell-box.json"));
  MeshOptions options;
  options.mode = MeshOptions::Mode::MaxEdge;
  options.maxEdge = 0.001;  // mm: a trillion elements
  const std::string m = inputError([&] { buildMesh(box, options); });
  EXPECT_CONTAINS(m, "--max-edge 0.001 would make about ");
  EXPECT_CONTAINS(m, "elements, needing about ");
  EXPECT_CONTAINS(m, "Use a coarser mesh, e.g. --max-edge ");
  options.mode = MeshOptions::Mode::Count;
  options.count = 2000000;
  EXPECT_CONTAINS(inputError([&] { buildMesh(box, options); }), "--subdivide 2000000 would make about");
}

TEST(RobustInput, FormFactorMatrixThatCannotFitIsRefused) {
  EXPECT_CONTAINS(inputError([] { zeroFormFactorMatrix(10000000); }),
                  "the form-factor matrix of 10,000,000 elements needs 728 TB");
  EXPECT_EQ(zeroFormFactorMatrix(3).sum(), 0.0);
}

}  // namespace
}  // namespace rt
