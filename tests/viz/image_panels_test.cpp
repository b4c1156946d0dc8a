// Images side by side: one image shape per panel with its title, a shared exposure, a colour bar for
// difference maps, and a PNG that shows the pictures.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "support/test_paths.h"
#include "support/vector_chart_check.h"
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

// The book's figures are SVG: a picture in a panel must be in the file (no reference to a definition the
// exporter left out), and an independent renderer must draw it there.
TEST(ImagePanels, TheSvgShowsThePictures) {
  if (const std::string missing = rt::test::missingVectorRenderers(); !missing.empty())
    GTEST_SKIP() << missing;
  const std::string path = rt::test::scratchDir("image-panels") + "/panels.svg";
  ImagePanelsOptions o;
  o.size = {600, 400, 96};
  RgbImage red(8, 8), blue(8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) red.at(x, y) = Rgb(1, 0, 0), blue.at(x, y) = Rgb(0, 0, 1);
  const Drawing drawing = imagePanelsDrawing({{"red", red}, {"blue", blue}}, o);
  writeImagePanelsFigure({{"red", red}, {"blue", blue}}, o, path);
  std::ifstream in(path);
  const std::string svg{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_EQ(svg.find("#vtkEmbeddedImage"), std::string::npos) << "a reference to an image the file lacks";
  EXPECT_NE(svg.find("data:image/png;base64,"), std::string::npos);

  const rt::test::RenderedChart page = rt::test::renderChart(path);
  ASSERT_TRUE(page.error.empty()) << page.error;
  // The centre of each picture, in the page's points (y down), is its colour.
  const std::array<int, 3> expected[2] = {{255, 0, 0}, {0, 0, 255}};
  int panel = 0;
  for (const Drawing::Shape& shape : drawing.shapes) {
    if (shape.kind != Drawing::Kind::Image) continue;
    const double cx = 0.5 * (shape.points[0].x() + shape.points[1].x());
    const double cy = drawing.height - 0.5 * (shape.points[0].y() + shape.points[1].y());
    const int px = static_cast<int>(cx * page.width / drawing.width);
    const int py = static_cast<int>(cy * page.height / drawing.height);
    const unsigned char* rgb = &page.rgb[3 * (static_cast<std::size_t>(py) * page.width + px)];
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(rgb[c], expected[panel][c], 60)
          << "panel " << panel << " channel " << c << " at " << px << "," << py;
    ++panel;
  }
  EXPECT_EQ(panel, 2);
}

}  // namespace
}  // namespace rt::viz
