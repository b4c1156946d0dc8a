// Images side by side: one image shape per panel with its title, a shared exposure, a colour bar for
// difference maps, and a PNG that shows the pictures.
#include <gtest/gtest.h>

#include "support/test_paths.h"
#include "viz/image_panels.h"
#include "viz_test_support.h"

namespace rt::viz {
namespace {

RgbImage gradient(int w, int h, double scale) {
  RgbImage image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.at(x, y) = scale * Rgb(x + 1.0, y + 1.0, 0.5 * (x + y + 2.0)) / w;
  return image;
}

TEST(ImagePanels, OneImagePerPanelUnderItsTitle) {
  ImagePanelsOptions o;
  o.size = {900, 500, 96};
  o.title = "Two pictures";
  const Drawing d = imagePanelsDrawing({{"left", gradient(16, 16, 1)}, {"right", gradient(16, 16, 2)}}, o);
  EXPECT_EQ(d.count(Drawing::Kind::Image), 2u);
  std::vector<std::string> words;
  for (const auto& s : d.shapes)
    if (s.kind == Drawing::Kind::Text) words.push_back(s.text);
  EXPECT_EQ(words, (std::vector<std::string>{"Two pictures", "left", "right"}));
  for (const auto& s : d.shapes)
    if (s.kind == Drawing::Kind::Image) {
      EXPECT_EQ(s.pixels.size(), 256u);
      EXPECT_GE(s.points[0].x(), 0);
      EXPECT_LE(s.points[1].x(), d.width);
      EXPECT_NEAR(s.points[1].x() - s.points[0].x(), s.points[1].y() - s.points[0].y(), 1e-9) << "square";
    }
  EXPECT_THROW(imagePanelsDrawing({}, o), std::invalid_argument);
}

TEST(ImagePanels, PicturesShareTheFirstPanelsExposure) {
  ImagePanelsOptions o;
  const std::vector<ImagePanel> panels{{"a", gradient(10, 10, 1)}, {"b", gradient(10, 10, 100)}};
  const double exposure = panelExposure(panels, o);
  // The first panel's brightest pixels (channel 1.0) set it; the second, a hundred times brighter, does not.
  EXPECT_NEAR(exposure, 1.0, 0.15);
  o.exposure = 3;
  EXPECT_EQ(panelExposure(panels, o), 3);
}

TEST(ImagePanels, DifferenceMapsGetAColourBar) {
  ImagePanelsOptions o;
  o.scalar = true;
  o.legend = "relative";
  const Drawing d = imagePanelsDrawing({{"error", gradient(8, 8, 0.1)}}, o);
  bool legend = false;
  for (const auto& s : d.shapes) legend = legend || s.text == "relative";
  EXPECT_TRUE(legend);
  EXPECT_GT(d.count(Drawing::Kind::Polygon), 50u) << "the bar's colour steps";
}

TEST(ImagePanels, ThePngShowsThePictures) {
  const std::string path = rt::test::scratchDir("image-panels") + "/panels.png";
  ImagePanelsOptions o;
  o.size = {600, 400, 96};
  writeImagePanelsFigure({{"a", gradient(32, 32, 1)}, {"b", gradient(32, 32, 0.5)}}, o, path);
  const vizt::PngStats stats = vizt::pngStats(path);
  EXPECT_EQ(stats.width, 600);
  EXPECT_GT(stats.stddev, 20) << "not a blank page";
  EXPECT_LT(stats.mean[1], 250) << "the pictures, not a white page";
}

}  // namespace
}  // namespace rt::viz
