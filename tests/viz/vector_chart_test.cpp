// Charts in SVG and PDF as other programs draw them (rsvg-convert for SVG, pdftoppm and pdftotext for PDF):
// every curve a thin line whatever the range of its axes (not a band as wide as the plot), text anchored
// where SVG has an anchor, tick labels beside their axis and clear of the axis titles. Through
// writeLineChart, which draws every chart of the program, and through `radiosity figure`.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/test_paths.h"
#include "support/vector_chart_check.h"
#include "viz/chart.h"
#include "viz/colour_map.h"

namespace rt::viz {
namespace {

// Radiosity settling within a thousandth of its value: on a linear axis that is a range of 1e-3 over the
// plot's height, where a stroke in data units would be wider than the plot.
std::vector<Series> settling() {
  Series jacobi{"Jacobi", {}, {}}, gaussSeidel{"Gauss-Seidel", {}, {}};
  for (int k = 0; k <= 120; ++k) {
    jacobi.x.push_back(k);
    jacobi.y.push_back(1.0 + 1e-3 * std::pow(0.95, k));
    gaussSeidel.x.push_back(k);
    gaussSeidel.y.push_back(1.0 + 1e-3 * std::pow(0.9, k));
  }
  return {jacobi, gaussSeidel};
}

TEST(VectorChart, CurvesAreThinLinesAndTextIsInPlaceOnANarrowLinearRange) {
  RT_REQUIRE_VECTOR_RENDERERS();
  const std::string dir = test::scratchDir("vector_chart_linear");
  ChartOptions o;
  o.title = "Radiosity of the floor";
  o.xLabel = "iteration";
  o.yLabel = "floor radiosity";
  o.width = 900;
  o.height = 600;
  o.markers = false;  // the lines alone: their width is measured
  for (const std::string extension : {".svg", ".pdf"}) {
    writeLineChart(settling(), o, dir + "/settling" + extension);
    test::expectReadableChart(dir + "/settling" + extension, {"iteration", "floor", "radiosity"}, 2);
  }
}

TEST(VectorChart, CurvesAreThinLinesAndTextIsInPlaceOnALogarithmicAxis) {
  RT_REQUIRE_VECTOR_RENDERERS();
  const std::string dir = test::scratchDir("vector_chart_log");
  std::vector<Series> series = settling();
  for (Series& s : series)
    for (double& y : s.y) y -= 1.0;
  ChartOptions o;
  o.title = "Residual against iteration";
  o.xLabel = "iteration";
  o.yLabel = "relative residual";
  o.logY = true;
  o.markers = false;
  for (const std::string extension : {".svg", ".pdf"}) {
    writeLineChart(series, o, dir + "/residual" + extension);
    test::expectReadableChart(dir + "/residual" + extension, {"iteration", "relative", "residual"}, 2);
  }
}

// The command a reader types for the convergence of Southwell's method, in both vector formats.
TEST(VectorChart, TheFigureCommandsConvergenceChartIsReadableInSvgAndPdf) {
  RT_REQUIRE_VECTOR_RENDERERS();
  const std::string dir = test::scratchDir("vector_chart_cli");
  for (const std::string extension : {".svg", ".pdf"}) {
    const std::string output = dir + "/c" + extension;
    std::string log;
    ASSERT_EQ(test::runCommand(test::cliPath() + " figure " + test::sourcePath("scenes/cornell-box.json") +
                                   " --view convergence --solver southwell --output " + output,
                               &log),
              0)
        << log;
    // --solver is the scene's solver: the chart compares all four, Jacobi and Gauss-Seidel first.
    test::expectReadableChart(output, {"iteration", "relative", "residual"}, 2);
  }
}

// A fitted power law beside its measured points, as the book's error-against-n figures draw it: in the
// measured series' colour (no second colour, which a reader would take for another series), without a legend
// entry of its own, and the measured curve still a thin line.
TEST(VectorChart, AFitTakesItsSeriesColourAndNoLegendEntry) {
  RT_REQUIRE_VECTOR_RENDERERS();
  const std::string dir = test::scratchDir("vector_chart_fit");
  Series measured{"measured: slope -0.50", {100, 400, 1600, 6400}, {0.1, 0.052, 0.024, 0.0126}};
  const Series fit = fittedPowerLaw(measured, -0.5, 0);
  EXPECT_EQ(fit.fitOf, 0);
  ChartOptions o;
  o.title = "Noise against rays";
  o.xLabel = "rays";
  o.yLabel = "error";
  o.logX = o.logY = true;
  for (const std::string extension : {".svg", ".pdf"}) {
    const std::string path = dir + "/fit" + extension;
    writeLineChart({measured, fit}, o, path);
    const test::RenderedChart page = test::renderChart(path);
    ASSERT_TRUE(page.error.empty()) << page.error;
    const Rgb8 first = qualitativeColour(0), second = qualitativeColour(1);
    const test::Stroke curve = test::measureStroke(page, {first[0], first[1], first[2]}, 30);
    EXPECT_GT(curve.pixels, 100) << extension;
    EXPECT_LE(curve.width, test::kThinLine) << extension;
    EXPECT_EQ(test::measureStroke(page, {second[0], second[1], second[2]}, 30).pixels, 0)
        << extension << ": the fit has a colour of its own";
    for (const test::Word& w : page.words)
      EXPECT_EQ(w.text.find("fit"), std::string::npos) << extension << ": a legend entry '" << w.text << "'";
  }
  EXPECT_THROW(writeLineChart({measured, Series{"fit of nothing", {1, 2}, {1, 2}, 5}}, o, dir + "/bad.png"),
               std::invalid_argument);
}

// A legend goes to the corner its curves leave empty: a rising curve passes through the top right, so the
// legend stands at the top left; a falling one leaves the top right free.
TEST(VectorChart, TheLegendTakesTheCornerTheCurvesLeaveEmpty) {
  RT_REQUIRE_VECTOR_RENDERERS();
  const std::string dir = test::scratchDir("vector_chart_legend");
  ChartOptions o;
  o.title = "Links against n";
  o.xLabel = "elements n";
  o.yLabel = "count";
  o.logX = o.logY = true;
  const std::vector<double> n = {100, 400, 1600, 6400};
  auto legendLeft = [&](const Series& curve, const std::string& name) {
    const std::string path = dir + "/" + name + ".svg";
    writeLineChart({curve}, o, path);
    const test::RenderedChart page = test::renderChart(path);
    EXPECT_TRUE(page.error.empty()) << page.error;
    for (const test::Word& w : page.words)
      if (w.text.find("curve") != std::string::npos) return w.xMax < 0.5 * page.width;
    ADD_FAILURE() << name << ": no legend entry";
    return false;
  };
  EXPECT_TRUE(legendLeft({"rising curve", n, {1e4, 1.6e5, 2.6e6, 4.1e7}}, "rising"));
  EXPECT_FALSE(legendLeft({"falling curve", n, {0.1, 0.05, 0.025, 0.0125}}, "falling"));
}

// Text with a '|' ("|K_ij|" on the colour bar, "largest |value|" in the title of a blocked matrix): in the
// PDF it is text, as every other word, and no red box stands beside it.
TEST(VectorChart, TheMatrixPdfHasItsWordsAndNoStrayBox) {
  RT_REQUIRE_VECTOR_RENDERERS();
  const std::string dir = test::scratchDir("vector_matrix");
  const std::string views[] = {"--view matrix --matrix K --log", "--view matrix --subdivide 4"};
  const std::string words[] = {"|K_ij|", "|value|)"};
  for (int k = 0; k < 2; ++k) {
    const std::string output = dir + "/m" + std::to_string(k) + ".pdf";
    std::string log;
    ASSERT_EQ(test::runCommand(test::cliPath() + " figure " + test::sourcePath("scenes/cornell-box.json") +
                                   " " + views[k] + " --output " + output,
                               &log),
              0)
        << log;
    const test::RenderedChart page = test::renderChart(output);
    ASSERT_TRUE(page.error.empty()) << page.error;
    EXPECT_EQ(test::measureStroke(page, test::kStrayRed).pixels, 0) << views[k] << ": a red box";
    bool found = false;
    for (const test::Word& w : page.words) found = found || w.text == words[k];
    EXPECT_TRUE(found) << views[k] << ": '" << words[k] << "' is not text in the PDF";
  }
}

}  // namespace
}  // namespace rt::viz
