// Mesh edges are lines of their own: from inside a room no face turns the edge colour (the ceiling light
// stays the brightest face), and from outside a closed room the edges of the walls culled from behind stay
// hidden.
#include <gtest/gtest.h>

#include <vtkCamera.h>
#include <vtkNew.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <set>

#include "core/io/scene_loader.h"
#include "support/test_paths.h"
#include "viz/mesh_edges.h"
#include "viz/scene_view.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

Scene furnace() {
  return loadScene(test::sourcePath("scenes/furnace-cube-one-light.json"));
}

Mesh subdivided(const Scene& scene, int count) {
  MeshOptions options;
  options.mode = MeshOptions::Mode::Count;
  options.count = count;
  return buildMesh(scene, options);
}

// The light at 1 W/m^2 over its reflection, the grey walls at a third of it: the ceiling is the brightest.
RgbField lit(const Mesh& mesh) {
  return (mesh.emission.array() + 0.35).matrix();
}

SceneViewOptions sized(bool edges) {
  SceneViewOptions options;
  options.image.width = 320;
  options.image.height = 240;
  options.image.exposure = 0.8;
  options.image.showEdges = edges;
  return options;
}

// The pixels of elements of `patches`: a picture of them in the top colour of the map, the rest in its
// bottom colour.
std::vector<bool> maskOf(const Mesh& mesh, const Camera& camera, const std::set<int>& patches,
                         const std::string& path) {
  SceneViewOptions options = sized(false);
  options.colouring = SceneColouring::Scalar;
  options.colourBar = false;
  options.legend.min = 0;
  options.legend.max = 1;
  SceneViewData data;
  data.scalar.resize(static_cast<Eigen::Index>(mesh.size()));
  for (std::size_t e = 0; e < mesh.size(); ++e)
    data.scalar[static_cast<Eigen::Index>(e)] = patches.count(mesh.elements[e].patch) ? 1.0 : 0.0;
  writeSceneFigure(mesh, camera, data, options, path);
  const vizt::PngLuminance mask = vizt::pngLuminance(path);
  std::vector<bool> inside(mask.values.size());
  for (std::size_t i = 0; i < inside.size(); ++i) inside[i] = mask.values[i] > 150;  // viridis: yellow
  return inside;
}

int patchNamed(const Scene& scene, const std::string& surface) {
  for (std::size_t p = 0; p < scene.patches.size(); ++p)
    if (scene.surfaces[static_cast<std::size_t>(scene.patches[p].surface)].name == surface)
      return static_cast<int>(p);
  return -1;
}

TEST(MeshEdges, EveryElementEdgeOnce) {
  const Mesh mesh = subdivided(furnace(), 2);  // 24 quads of a closed cube
  const MeshEdgeTable table = meshEdgeTable(mesh);
  EXPECT_EQ(table.edges.size(), 48u);  // 96 corners, every edge between two quads
  std::vector<int> uses(table.edges.size(), 0);
  for (int edge : table.cornerEdge) ++uses[static_cast<std::size_t>(edge)];
  EXPECT_TRUE(std::all_of(uses.begin(), uses.end(), [](int n) { return n == 2; }));
  std::set<std::array<int, 2>> distinct(table.edges.begin(), table.edges.end());
  EXPECT_EQ(distinct.size(), table.edges.size());
}

TEST(MeshEdges, FromInsideTheFurnaceNoFaceTakesTheEdgeColourAndTheLightIsTheBrightest) {
  const Scene scene = furnace();
  const Mesh mesh = subdivided(scene, 3);
  const std::string dir = test::scratchDir("mesh_edges_inside");
  SceneViewData data;
  data.B = lit(mesh);
  struct View {
    std::string name;
    Camera camera;
    bool ceiling;  // in view
  };
  Camera centre;  // in the middle of the cube, looking down at a far corner: every face reaches behind it
  centre.position = {0.5, 0.5, 0.5};
  centre.target = {0, 0.3, 0};
  centre.fovYDegrees = 70;
  Camera up;  // low in a corner, looking up at the opposite upper corner: the ceiling fills the top
  up.position = {0.8, 0.3, 0.85};
  up.target = {0.2, 0.75, 0.2};
  up.fovYDegrees = 70;
  const std::vector<View> views = {
      {"scene", *scene.camera, false}, {"centre", centre, false}, {"up", up, true}};
  for (const auto& [name, camera, ceilingInView] : views) {
    SCOPED_TRACE(name);
    writeSceneFigure(mesh, camera, data, sized(true), dir + "/" + name + "-edges.png");
    writeSceneFigure(mesh, camera, data, sized(false), dir + "/" + name + "-plain.png");
    const vizt::PngLuminance edges = vizt::pngLuminance(dir + "/" + name + "-edges.png");
    const vizt::PngLuminance plain = vizt::pngLuminance(dir + "/" + name + "-plain.png");
    // Only the lines differ from the picture without edges: a face in the edge colour would be a tenth of
    // the picture or more.
    int darkened = 0, dark = 0;
    for (std::size_t i = 0; i < edges.values.size(); ++i) {
      darkened += plain.values[i] - edges.values[i] > 40;
      dark += edges.values[i] < 40;
    }
    const double pixels = static_cast<double>(edges.values.size());
    std::cout << name << ": " << 100.0 * darkened / pixels << " % of the pixels darkened by the edges, "
              << 100.0 * dark / pixels << " % dark\n";
    EXPECT_GT(darkened, 0) << "no edges drawn";
    EXPECT_LT(darkened / pixels, 0.06);
    EXPECT_LT(dark / pixels, 0.06);

    if (!ceilingInView) continue;
    // The ceiling's pixels are the brightest of the picture.
    const std::vector<bool> ceiling =
        maskOf(mesh, camera, {patchNamed(scene, "ceiling")}, dir + "/" + name + "-ceiling.png");
    double ceilingSum = 0, restSum = 0;
    int ceilingCount = 0, restCount = 0;
    for (std::size_t i = 0; i < ceiling.size(); ++i) {
      (ceiling[i] ? ceilingSum : restSum) += edges.values[i];
      ++(ceiling[i] ? ceilingCount : restCount);
    }
    ASSERT_GT(ceilingCount, static_cast<int>(pixels / 5)) << "the ceiling is out of view";
    std::cout << name << ": ceiling " << ceilingSum / ceilingCount << ", the rest " << restSum / restCount
              << "\n";
    EXPECT_GT(ceilingSum / ceilingCount, restSum / restCount + 30);
  }
}

TEST(MeshEdges, FromOutsideAClosedBoxTheCulledWallsEdgesAreNotDrawn) {
  const Scene scene = furnace();
  const Mesh mesh = subdivided(scene, 4);
  // From this corner outside, the floor, back and left walls face the camera (inwards); the ceiling, front
  // and right walls are seen from behind, culled.
  Camera outside;
  outside.position = {2.2, 1.8, 2.5};
  outside.target = {0.5, 0.5, 0.5};
  outside.fovYDegrees = 40;

  auto lines = MeshEdgeLines::make(mesh, {0, 0, 0}, 1.0);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(outside.position.data());
  camera->SetFocalPoint(outside.target.data());
  EXPECT_TRUE(lines->follow(*camera));
  EXPECT_EQ(lines->shownEdges(), 3u * 40u - 3u * 4u);  // three 4 x 4 grids, 4 edges on each shared side
  camera->SetFocalPoint(0.4, 0.6, 0.5);                // a turn of the head: the same faces, the lines stay
  EXPECT_FALSE(lines->follow(*camera));
  camera->SetPosition(0.5, 0.5, 0.5);  // inside: every face
  EXPECT_TRUE(lines->follow(*camera));
  EXPECT_EQ(lines->shownEdges(), 6u * 40u - 12u * 4u);

  // The picture of the closed box is the picture of its three far walls alone.
  Scene far = scene;
  far.patches.clear();
  for (const Patch& patch : scene.patches) {
    const std::string& surface = scene.surfaces[static_cast<std::size_t>(patch.surface)].name;
    if (surface == "floor" || surface == "back" || surface == "left") far.patches.push_back(patch);
  }
  const Mesh farMesh = subdivided(far, 4);
  const std::string dir = test::scratchDir("mesh_edges_outside");
  SceneViewData data, farData;
  data.B = lit(mesh);
  farData.B = lit(farMesh);
  writeSceneFigure(mesh, outside, data, sized(true), dir + "/box.png");
  writeSceneFigure(farMesh, outside, farData, sized(true), dir + "/far.png");
  writeSceneFigure(farMesh, outside, farData, sized(false), dir + "/far-plain.png");
  const vizt::PngLuminance box = vizt::pngLuminance(dir + "/box.png");
  const vizt::PngLuminance farOnly = vizt::pngLuminance(dir + "/far.png");
  const vizt::PngLuminance plain = vizt::pngLuminance(dir + "/far-plain.png");
  int extra = 0, edgePixels = 0;
  for (std::size_t i = 0; i < box.values.size(); ++i) {
    extra += std::abs(box.values[i] - farOnly.values[i]) > 40;
    edgePixels += std::abs(plain.values[i] - farOnly.values[i]) > 40;
  }
  std::cout << extra << " pixels differ from the far walls alone, whose edges cover " << edgePixels << "\n";
  EXPECT_GT(edgePixels, 500) << "no edges drawn";
  EXPECT_LT(extra, edgePixels / 20);
}

// Every frame of an orbit asks for the edges again: below the stand-in threshold the full mesh is drawn while
// the camera moves, and choosing its edges must stay a small part of a frame.
TEST(MeshEdges, FollowingTheCameraOverALargeSceneIsCheap) {
  const Scene scene = loadScene(test::sourcePath("scenes/museum-50k.obj"));
  const Mesh mesh = buildMesh(scene);
  const auto start = std::chrono::steady_clock::now();
  auto lines = MeshEdgeLines::make(mesh, {0, 0, 0}, 1.0);
  const double made =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const Camera view = scene.cameraOrDefault();
  vtkNew<vtkCamera> camera;
  camera->SetPosition(view.position.data());
  camera->SetFocalPoint(view.target.data());
  EXPECT_TRUE(lines->follow(*camera));
  const double first = lines->lastChoiceMilliseconds();
  camera->SetFocalPoint((view.target + Vec3(0.01, 0, 0)).eval().data());
  EXPECT_FALSE(lines->follow(*camera));
  const double same = lines->lastChoiceMilliseconds();
  camera->SetPosition((2 * view.target - view.position).eval().data());  // the other side: other faces
  EXPECT_TRUE(lines->follow(*camera));
  const double other = lines->lastChoiceMilliseconds();
  std::cout << mesh.size() << " elements, " << lines->shownEdges() << " edges shown: built in " << made
            << " ms; a choice " << first << " ms, " << same << " ms when the faces stay, " << other
            << " ms when they change\n";
  EXPECT_LT(same, 10.0);
  EXPECT_LT(other, 40.0);
}

}  // namespace
}  // namespace rt::viz
