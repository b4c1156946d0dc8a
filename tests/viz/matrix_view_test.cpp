// The matrix view: cells, numbers, separators, blocks; the files in every format.
#include <gtest/gtest.h>

#include "support/test_paths.h"
#include "viz/matrix_view.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

Eigen::MatrixXd sample(int n) {
  Eigen::MatrixXd m(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) m(r, c) = r == c ? 0.0 : 1.0 / (1 + std::abs(r - c));
  return m;
}

TEST(MatrixView, SmallMatrixHasOneCellAndOneNumberPerEntry) {
  MatrixViewOptions o;
  o.groups = {0, 0, 1, 1};
  const Drawing d = matrixDrawing(sample(4), o);
  std::size_t numbers = 0, separators = 0;
  for (const auto& s : d.shapes) {
    if (s.kind == Drawing::Kind::Text && (s.text == "0" || s.text.find('.') != std::string::npos)) ++numbers;
    if (s.kind == Drawing::Kind::Polyline && s.points.size() == 2 && s.stroke == Rgb8{255, 255, 255})
      ++separators;
  }
  EXPECT_GE(numbers, 16u);
  EXPECT_EQ(separators, 2u);  // one group change: a vertical and a horizontal line
  EXPECT_GE(d.count(Drawing::Kind::Polygon), 16u);
}

// A nearly constant matrix stays nearly one colour: the unit cube's 0.1998 and 0.2000 must not look like the
// two ends of the map (log and linear scales alike).
TEST(MatrixView, ANearlyConstantMatrixIsNotStretchedOverTheColourMap) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Constant(2, 2, 0.2000);
  m(0, 1) = 0.1998;
  for (bool log : {true, false}) {
    MatrixViewOptions o;
    o.logScale = log;
    const Drawing d = matrixDrawing(m, o);
    // The first four filled polygons are the cells (row 0 left to right, then row 1).
    std::vector<Rgb8> cells;
    for (const auto& s : d.shapes)
      if (s.kind == Drawing::Kind::Polygon && s.filled && cells.size() < 4) cells.push_back(s.fill);
    ASSERT_EQ(cells.size(), 4u);
    int largest = 0;
    for (int ch = 0; ch < 3; ++ch)
      largest = std::max(largest, std::abs(int(cells[0][ch]) - int(cells[1][ch])));
    EXPECT_LT(largest, 12) << (log ? "log" : "linear") << " scale: 0.2000 and 0.1998 look far apart";
  }
}

TEST(MatrixView, LargeMatrixIsShownAsBlocksWithoutNumbers) {
  MatrixViewOptions o;
  o.maxCells = 50;
  const Drawing d = matrixDrawing(sample(200), o);
  // 200 / 50 = 4: 50 x 50 cells plus the colour bar's strips.
  EXPECT_GE(d.count(Drawing::Kind::Polygon), 2500u);
  EXPECT_LT(d.count(Drawing::Kind::Polygon), 2700u);
}

TEST(MatrixView, RejectsNonSquareAndBadGroups) {
  EXPECT_THROW(matrixDrawing(Eigen::MatrixXd::Zero(2, 3), {}), std::invalid_argument);
  MatrixViewOptions o;
  o.groups = {0};
  EXPECT_THROW(matrixDrawing(sample(3), o), std::invalid_argument);
}

TEST(MatrixView, SvgAndPdfAreVectors) {
  const std::string dir = test::scratchDir("matrix_view");
  MatrixViewOptions o;
  o.size = {500, 430, 96};
  o.selectedRow = 1;
  writeMatrixFigure(sample(5), o, dir + "/m.svg");
  writeMatrixFigure(sample(5), o, dir + "/m.pdf");
  writeMatrixFigure(sample(5), o, dir + "/m.png");
  const std::string svg = vizt::readFile(dir + "/m.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_TRUE(svg.find("<polygon") != std::string::npos || svg.find("<path") != std::string::npos);
  EXPECT_EQ(svg.find("<image"), std::string::npos);
  const std::string pdf = vizt::readFile(dir + "/m.pdf");
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
  EXPECT_GT(pdf.size(), 2000u);
  EXPECT_GT(vizt::pngStats(dir + "/m.png").stddev, 20.0);
}

}  // namespace
}  // namespace rt::viz
