// The local lines' hit chart: one bar, one error bar and one reference mark per surface, every label drawn,
// and an empty row list refused.
#include "viz/hits_chart.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace rt::viz {
namespace {

bool hasText(const Drawing& d, const std::string& text) {
  return std::any_of(d.shapes.begin(), d.shapes.end(), [&](const Drawing::Shape& s) {
    return s.kind == Drawing::Kind::Text && s.text == text;
  });
}

TEST(HitsChart, DrawsABarAnErrorBarAndAMarkPerSurface) {
  const std::vector<HitRow> rows{{"floor", 0.4, 0.01, 0.41}, {"tall_block", 0.05, 0.004, 0.045}};
  HitsChartOptions o;
  o.title = "4000 local lines";
  const Drawing d = hitsDrawing(rows, o);
  EXPECT_TRUE(hasText(d, "floor"));
  EXPECT_TRUE(hasText(d, "tall_block"));
  EXPECT_TRUE(hasText(d, "4000 local lines"));
  // Bars and the legend's swatch; reference diamonds and the legend's.
  EXPECT_EQ(d.count(Drawing::Kind::Polygon), 2u * rows.size() + 2u);
  // The bars' widths are in proportion to the estimates.
  std::vector<double> widths;
  for (const Drawing::Shape& s : d.shapes)
    if (s.kind == Drawing::Kind::Polygon && s.points.size() == 4 && s.points[0].y() == s.points[1].y())
      widths.push_back(std::abs(s.points[1].x() - s.points[0].x()));
  ASSERT_GE(widths.size(), 2u);
  EXPECT_NEAR(widths[0] / widths[1], 0.4 / 0.05, 1e-9);
}

TEST(HitsChart, NeedsRows) {
  EXPECT_THROW(hitsDrawing({}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace rt::viz
