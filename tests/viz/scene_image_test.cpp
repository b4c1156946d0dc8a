// renderRadiosityImage and the scene view: files are written, not blank, and follow the data.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_paths.h"
#include "viz/scene_image.h"
#include "viz/scene_view.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

TEST(SceneImage, RendersANonBlankPngOfTheRequestedSize) {
  const Scene scene = vizt::openRoom();
  MeshOptions meshOptions;
  meshOptions.mode = MeshOptions::Mode::Count;
  meshOptions.count = 6;
  const Mesh mesh = buildMesh(scene, meshOptions);
  const std::string dir = test::scratchDir("scene_image");
  ImageOptions options;
  options.width = 320;
  options.height = 240;
  renderRadiosityImage(mesh, vizt::syntheticRadiosity(mesh), *scene.camera, options, dir + "/room.png");
  const vizt::PngStats stats = vizt::pngStats(dir + "/room.png");
  EXPECT_EQ(stats.width, 320);
  EXPECT_EQ(stats.height, 240);
  EXPECT_GT(stats.stddev, 20.0);
  EXPECT_GT(stats.mean[0] + stats.mean[1] + stats.mean[2], 90.0);
  // The red wall shows on the left half: red dominates somewhere, green on the other side.
  EXPECT_GT(stats.mean[0], 40.0);
  EXPECT_GT(stats.mean[1], 40.0);
}

TEST(SceneImage, BlackRadiosityGivesADarkRoomOnTheBackground) {
  const Scene scene = vizt::openRoom();
  const Mesh mesh = buildMesh(scene);
  const std::string dir = test::scratchDir("scene_image_black");
  ImageOptions options;
  options.width = 200;
  options.height = 150;
  options.exposure = 1.0;
  renderRadiosityImage(mesh, RgbField::Zero(static_cast<Eigen::Index>(mesh.size()), 3), *scene.camera,
                       options, dir + "/black.png");
  const vizt::PngStats stats = vizt::pngStats(dir + "/black.png");
  // The room covers most of the image and is black; the grey background frames it.
  EXPECT_LT(stats.mean[0], 60.0);
  EXPECT_GT(stats.stddev, 5.0);
}

TEST(SceneImage, UnwritablePathNamesThePath) {
  const Scene scene = vizt::openRoom();
  const Mesh mesh = buildMesh(scene);
  ImageOptions options;
  options.width = 64;
  options.height = 64;
  try {
    renderRadiosityImage(mesh, vizt::syntheticRadiosity(mesh), *scene.camera, options,
                         "/nonexistent/dir/x.png");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/x.png"), std::string::npos);
  }
}

TEST(SceneView, WrongSizedDataIsRejected) {
  const Mesh mesh = buildMesh(vizt::openRoom());
  SceneViewData data;
  data.B = RgbField::Zero(2, 3);
  EXPECT_THROW(paintScene(mesh, data, {}), std::invalid_argument);
}

TEST(SceneView, PdfEmbedsTheRenderedImage) {
  const Scene scene = vizt::openRoom();
  const Mesh mesh = buildMesh(scene);
  SceneViewData data;
  data.B = vizt::syntheticRadiosity(mesh);
  SceneViewOptions options;
  options.image.width = 200;
  options.image.height = 160;
  const std::string dir = test::scratchDir("scene_view_pdf");
  writeSceneFigure(mesh, *scene.camera, data, options, dir + "/room.pdf");
  const std::string pdf = vizt::readFile(dir + "/room.pdf");
  ASSERT_GT(pdf.size(), 500u);
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
  EXPECT_NE(pdf.find("/Subtype /Image"), std::string::npos);
  EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
}

}  // namespace
}  // namespace rt::viz
