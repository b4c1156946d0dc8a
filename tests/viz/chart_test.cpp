// writeLineChart: PNG not blank; SVG and PDF are true vectors.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "support/test_paths.h"
#include "viz/chart.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

std::vector<Series> convergence() {
  Series jacobi{"Jacobi", {}, {}}, gaussSeidel{"Gauss-Seidel", {}, {}};
  for (int k = 1; k <= 30; ++k) {
    jacobi.x.push_back(k);
    jacobi.y.push_back(std::pow(0.7, k));
    gaussSeidel.x.push_back(k);
    gaussSeidel.y.push_back(std::pow(0.45, k));
  }
  return {jacobi, gaussSeidel};
}

ChartOptions options() {
  ChartOptions o;
  o.title = "Residual against iteration";
  o.xLabel = "iteration";
  o.yLabel = "relative residual";
  o.logY = true;
  o.width = 640;
  o.height = 420;
  return o;
}

TEST(Chart, PngIsNotBlank) {
  const std::string path = test::scratchDir("chart_png") + "/chart.png";
  writeLineChart(convergence(), options(), path);
  const vizt::PngStats stats = vizt::pngStats(path);
  EXPECT_EQ(stats.width, 640);
  EXPECT_EQ(stats.height, 420);
  EXPECT_GT(stats.stddev, 10.0);
}

TEST(Chart, SvgHasVectorPaths) {
  const std::string path = test::scratchDir("chart_svg") + "/chart.svg";
  writeLineChart(convergence(), options(), path);
  const std::string svg = vizt::readFile(path);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_TRUE(svg.find("<path") != std::string::npos || svg.find("<polyline") != std::string::npos ||
              svg.find("<polygon") != std::string::npos);
  EXPECT_EQ(svg.find("<image"), std::string::npos);  // no raster
  // Text is drawn as paths; the title, axes and series are named in the SVG's metadata.
  EXPECT_NE(svg.find("<title>\n    Residual against iteration"), std::string::npos);
  EXPECT_NE(svg.find("x: iteration; y: relative residual; series: Jacobi, Gauss-Seidel"), std::string::npos);
  EXPECT_EQ(svg.find("VTK Exported Scene"), std::string::npos);
}

TEST(Chart, PdfHasContent) {
  const std::string path = test::scratchDir("chart_pdf") + "/chart.pdf";
  writeLineChart(convergence(), options(), path);
  const std::string pdf = vizt::readFile(path);
  ASSERT_GT(pdf.size(), 1000u);
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
}

TEST(Chart, NothingDrawableIsAnError) {
  ChartOptions o = options();
  EXPECT_THROW(writeLineChart({{"zero", {1, 2}, {0, 0}}}, o, test::scratchDir("chart_none") + "/c.png"),
               std::invalid_argument);
  EXPECT_THROW(writeLineChart(convergence(), o, test::scratchDir("chart_ext") + "/c.bmp"),
               std::invalid_argument);
}

}  // namespace
}  // namespace rt::viz
