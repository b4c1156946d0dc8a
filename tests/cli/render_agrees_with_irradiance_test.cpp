// radiosity render and radiosity irradiance are one two-pass method: the picture of the closed box with the
// light 1 cm below an uncut ceiling (the default mesh, cut along the light's outline, and the same second
// pass) shows at its floor pixels the radiosity the point query computes at the points those pixels see. The
// picture at its default gathers only at every eighth pixel and interpolates between them, except where
// other surfaces are near (beside the blocks' feet, in the room's corners), where it gathers more densely:
// a bilinear fit across a whole cell there is several per cent off. Pixels beside a silhouette show the mean
// over their square and are left out.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "core/io/rgb_image.h"
#include "core/io/scene_loader.h"
#include "core/pathtrace/path_tracer.h"
#include "core/pathtrace/tracing_scene.h"
#include "support/test_paths.h"

namespace rt::test {
namespace {

TEST(RenderAgreesWithIrradiance, TheTwoPassPictureShowsThePointQuerysRadiosityOnTheFloor) {
  const std::string dir = scratchDir("render-irradiance");
  const std::string scenePath = sourcePath("scenes/cornell-box-closed-light-1cm.json");
  const int size = 64;
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " render " + scenePath +
                           " --width 64 --height 64 --camera \"position 278 440 2 target "
                           "278 180 559 up 0 1 0 "
                           "fov_y_degrees 72\" --output " +
                           dir + "/two-pass.pfm",
                       &log),
            0)
      << log;
  EXPECT_NE(log.find("mesh: cut ceiling (patch 2) along the outline of light"), std::string::npos) << log;
  const RgbImage picture = readPfm(dir + "/two-pass.pfm");
  ASSERT_EQ(picture.width, size);

  // The floor points the centres of a grid of pixels in the picture's lower part see.
  const Scene scene = loadScene(scenePath);
  const TracingScene tracing(scene);
  const Camera camera{{278, 440, 2}, {278, 180, 559}, {0, 1, 0}, 72};  // the camera above, looking down
  struct Pixel {
    int x, y;
  };
  std::vector<Pixel> pixels;
  std::ofstream points(dir + "/points.csv");
  points << "x,y,z,nx,ny,nz\n";
  auto seesTheFloor = [&](int x, int y, Vec3* point) {
    const Vec3 d = cameraRay(camera, size, size, x + 0.5, y + 0.5);
    const RayHit hit = tracing.rays().firstHitAfter(camera.position, d, 0);
    *point = camera.position + hit.distance * d;
    return hit.element >= 0 && std::abs(point->y()) < 0.5;  // (Embree hits in single precision)
  };
  for (int y = 27; y < size - 1; y += 3)
    for (int x = 3; x < size - 1; x += 4) {
      Vec3 p, q;
      bool floorAround = seesTheFloor(x, y, &p);
      // A pixel whose neighbours see another surface (a block's foot) shows the mean over its square, not the
      // point at its centre.
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) floorAround = floorAround && seesTheFloor(x + dx, y + dy, &q);
      if (!floorAround) continue;
      pixels.push_back({x, y});
      points << p.x() << ",0," << p.z() << ",0,1,0\n";
    }
  points.close();
  ASSERT_GE(pixels.size(), 10u);
  ASSERT_EQ(runCommand(cliPath() + " irradiance " + scenePath + " --points " + dir +
                           "/points.csv --no-mesh-error --gather-rays 16384 --output " + dir + "/B.csv",
                       &log),
            0)
      << log;
  const auto rows = readCsv(dir + "/B.csv");
  ASSERT_EQ(rows.size(), pixels.size() + 1);
  double squares = 0, sum = 0;
  int values = 0;
  for (std::size_t k = 0; k < pixels.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      const double query =
          std::stod(rows[k + 1][static_cast<std::size_t>(column(rows[0], "B_" + std::string(1, "rgb"[c])))]);
      const double shown = picture.at(pixels[k].x, pixels[k].y)(c);
      const double relative = (shown - query) / query;
      // about four standard deviations of the picture's 1024-ray gather, over some 120 values
      EXPECT_LT(std::abs(relative), 0.04)
          << "pixel " << pixels[k].x << ", " << pixels[k].y << " channel " << c;
      squares += relative * relative;
      sum += relative;
      ++values;
    }
  // The picture's gather (1024 rays per pixel) adds noise; what bias there is comes from interpolating the
  // gathered light across cells beside the blocks' feet (docs/benchmarks.md), well under a per cent.
  EXPECT_LT(std::sqrt(squares / values), 0.015);
  EXPECT_LT(std::abs(sum / values), 0.0075);
}

}  // namespace
}  // namespace rt::test
