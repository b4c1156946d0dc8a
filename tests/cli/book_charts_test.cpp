// The book's charts as its readers see them: the numerical-stability lesson's Jacobi against Gauss-Seidel at
// rho = 0.95, in the HTML book's SVG (drawn by rsvg-convert) and on its page of book.pdf (drawn by pdftoppm),
// two thin lines with their text in place.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

#include "support/test_paths.h"
#include "support/vector_chart_check.h"

namespace {

namespace fs = std::filesystem;

// The first `text` on the page below `y` (the page's text may use the axis title's word too).
const rt::test::Word* find(const rt::test::RenderedChart& page, const std::string& text, double y = -1e9) {
  for (const auto& w : page.words)
    if (w.text == text && w.yMin > y) return &w;
  return nullptr;
}

TEST(BookCharts, JacobiAgainstGaussSeidelAreTwoThinLinesInTheSvgAndThePdf) {
  RT_REQUIRE_VECTOR_RENDERERS();
  if (!std::getenv("DISPLAY") && rt::test::runCommand("command -v xvfb-run") != 0)
    GTEST_SKIP() << "no X server";
  const fs::path out = rt::test::scratchDir("book_charts");
  const std::string prefix =
      std::getenv("DISPLAY") ? "" : "xvfb-run -a -s '-screen 0 1280x1024x24 -noreset' ";
  std::string log;
  const int status =
      rt::test::runCommand(prefix + rt::test::cliPath() + " book numerical-stability --quick --root " +
                               rt::test::sourcePath("") + " --output " + out.string(),
                           &log);
  if (status != 0 && log.find("no typesetting") != std::string::npos)
    GTEST_SKIP() << "built without typesetting";
  ASSERT_EQ(status, 0) << log;

  const fs::path svg = out / "numerical-stability" / "rho-095.svg";
  ASSERT_TRUE(fs::exists(svg)) << svg;
  rt::test::expectReadableChart(svg.string(), {"iteration", "relative", "residual"}, 2);

  // The page of book.pdf with the chart: its title and axis titles are words of that page; the figure is
  // the box from its title down to its x axis's title, as wide as a 4:3 figure of that height.
  std::string info;
  ASSERT_EQ(rt::test::runCommand("pdfinfo " + (out / "book.pdf").string(), &info), 0) << info;
  std::smatch pages;
  ASSERT_TRUE(std::regex_search(info, pages, std::regex("Pages:\\s+(\\d+)"))) << info;
  bool seen = false;
  for (int p = 1; p <= std::stoi(pages[1]) && !seen; ++p) {
    const rt::test::RenderedChart page = rt::test::renderChart((out / "book.pdf").string(), p);
    ASSERT_TRUE(page.error.empty()) << page.error;
    const rt::test::Word* title = find(page, "Convergence");
    if (!title) continue;
    const rt::test::Word* xTitle = find(page, "iteration", title->yMax);
    if (!xTitle) continue;
    seen = true;
    const double top = title->yMin - 4, bottom = xTitle->yMax + 4, centre = 0.5 * (title->xMin + title->xMax);
    const double half = 0.7 * (bottom - top);
    const rt::test::RenderedChart figure = rt::test::crop(page, centre - half, top, centre + half, bottom);
    SCOPED_TRACE("book.pdf, page " + std::to_string(p));
    const std::array<int, 3> colours[2] = {{230, 159, 0}, {86, 180, 233}};
    for (const auto& colour : colours) {
      const rt::test::Stroke stroke = rt::test::measureStroke(figure, colour);
      EXPECT_GT(stroke.pixels, 100) << "a curve is not drawn";
      EXPECT_LE(stroke.width, rt::test::kThinLine) << "a curve is a band " << stroke.width << " points wide";
    }
    for (const std::string& problem : rt::test::misplacedText(figure, {"iteration", "relative", "residual"}))
      ADD_FAILURE() << problem;
  }
  EXPECT_TRUE(seen) << "no page of book.pdf shows the convergence chart";
}

}  // namespace
