// The cluster view: boxes of the cluster tree drawn over the scene; the file is written, not blank, and the
// boxes change the picture.
#include <gtest/gtest.h>

#include "core/solvers/cluster_tree.h"
#include "support/test_paths.h"
#include "viz/cluster_view.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

std::vector<lesson::ClusterBox> boxesAtDepth(const ClusterTree& tree, int node, int depth) {
  const ClusterNode& k = tree.node(node);
  if (depth == 0 || k.leaf()) return {{k.box.min(), k.box.max()}};
  auto boxes = boxesAtDepth(tree, k.left, depth - 1);
  for (const auto& b : boxesAtDepth(tree, k.right, depth - 1)) boxes.push_back(b);
  return boxes;
}

TEST(ClusterView, DrawsTheBoxesOverTheScene) {
  const Scene scene = vizt::openRoom();
  MeshOptions meshOptions;
  meshOptions.mode = MeshOptions::Mode::Count;
  meshOptions.count = 4;
  const Mesh mesh = buildMesh(scene, meshOptions);
  const ClusterTree tree(mesh, mesh.reflectance);
  const std::string dir = test::scratchDir("cluster_view");
  ClusterViewOptions options;
  options.size = {320, 240, 96.0};
  options.caption = "clusters";
  const RgbField B = vizt::syntheticRadiosity(mesh);
  writeClusterFigure(mesh, B, *scene.camera, boxesAtDepth(tree, 0, 0), options, dir + "/root.png");
  writeClusterFigure(mesh, B, *scene.camera, boxesAtDepth(tree, 0, 3), options, dir + "/depth3.png");
  const vizt::PngStats stats = vizt::pngStats(dir + "/depth3.png");
  EXPECT_EQ(stats.width, 320);
  EXPECT_EQ(stats.height, 240);
  EXPECT_GT(stats.stddev, 20.0) << "not blank";
  EXPECT_GT(stats.mean[0] + stats.mean[1] + stats.mean[2], 60.0) << "not black";
  EXPECT_GT(vizt::pngDifference(dir + "/root.png", dir + "/depth3.png"), 0.5) << "the boxes show";
  EXPECT_THROW(writeClusterFigure(mesh, B, *scene.camera, {}, options, dir + "/none.png"),
               std::invalid_argument);
}

}  // namespace
}  // namespace rt::viz
