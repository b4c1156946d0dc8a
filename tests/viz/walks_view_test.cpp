// The walks view draws each recorded walk in the scene, one panel per solver, and refuses walks that leave
// the mesh or no panel at all.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_paths.h"
#include "viz/viz_test_support.h"
#include "viz/walks_view.h"

namespace rt::viz {
namespace {

Mesh roomMesh() {
  return vizt::openRoomMesh(2);
}

RecordedWalk walkOver(const Mesh& mesh, std::vector<int> elements) {
  RecordedWalk walk;
  walk.source = elements.front();
  walk.landings.assign(elements.begin() + 1, elements.end());
  for (int e : elements) walk.points.push_back(mesh.elements[static_cast<std::size_t>(e)].centroid);
  walk.weights.assign(walk.landings.size(), Eigen::RowVector3d::Ones());
  return walk;
}

TEST(WalksView, DrawsEachPanelsWalksOverTheRoom) {
  const Mesh mesh = roomMesh();
  const int last = static_cast<int>(mesh.size()) - 1;
  const std::vector<WalksPanel> panels{{"discrete", {walkOver(mesh, {0, last, 1}), walkOver(mesh, {2, 3})}},
                                       {"continuous", {walkOver(mesh, {last, 0})}}};
  const std::string path = test::scratchDir("walks-view") + "/walks.png";
  WalksViewOptions o;
  o.size = {480, 320, 96.0};
  writeWalksFigure(mesh, vizt::openRoom().cameraOrDefault(), panels, o, path);
  const vizt::PngStats stats = vizt::pngStats(path);
  EXPECT_EQ(stats.width, 480);
  EXPECT_GT(stats.stddev, 5.0) << "not blank";
}

TEST(WalksView, RefusesNoPanelsAndWalksOffTheMesh) {
  const Mesh mesh = roomMesh();
  const Camera camera = vizt::openRoom().cameraOrDefault();
  const std::string path = test::scratchDir("walks-view-refused") + "/walks.png";
  EXPECT_THROW(writeWalksFigure(mesh, camera, {}, {}, path), std::invalid_argument);
  RecordedWalk off = walkOver(mesh, {0, 1});
  off.landings.back() = static_cast<int>(mesh.size());
  EXPECT_THROW(writeWalksFigure(mesh, camera, {{"off", {off}}}, {}, path), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace rt::viz
