#include "support/vector_chart_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "support/test_paths.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

std::string shellQuoted(const std::string& path) {
  return "'" + path + "'";
}

bool readPpm(const std::string& path, RenderedChart& chart) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int maxValue = 0;
  in >> magic >> chart.width >> chart.height >> maxValue;
  in.get();
  if (magic != "P6" || chart.width <= 0 || chart.height <= 0 || maxValue != 255) return false;
  chart.rgb.resize(static_cast<std::size_t>(chart.width) * chart.height * 3);
  in.read(reinterpret_cast<char*>(chart.rgb.data()), static_cast<std::streamsize>(chart.rgb.size()));
  return static_cast<bool>(in);
}

std::vector<Word> readWords(const std::string& bboxHtml) {
  std::vector<Word> words;
  const std::regex word(
      "<word xMin=\"([0-9.]+)\" yMin=\"([0-9.]+)\" xMax=\"([0-9.]+)\" yMax=\"([0-9.]+)\">([^<]*)</word>");
  for (std::sregex_iterator it(bboxHtml.begin(), bboxHtml.end(), word), end; it != end; ++it)
    words.push_back(
        {(*it)[5], std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4])});
  return words;
}

double darkness(const RenderedChart& c, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * c.width + x) * 3;
  return 255.0 - (c.rgb[i] + c.rgb[i + 1] + c.rgb[i + 2]) / 3.0;
}

// Words whose boxes meet by less than this are side by side: the boxes run from the font's ascent to its
// descent, wider than the ink, VTK sets an axis title right beside its labels, and a viewer without VTK's
// font (librsvg, which ignores textLength, draws DejaVu Sans) draws a label up to 15 % wider. A title turned
// onto its labels covers them by the whole height of its letters, 12 pixels or more.
constexpr double kTouching = 8.0;

// The line (of `lines`, each `length` pixels long) whose pixels are darkest in sum; darkness(line, k).
template <typename Darkness>
int darkestLine(int lines, int length, Darkness darkness) {
  int darkest = 0;
  double best = -1;
  for (int l = 0; l < lines; ++l) {
    double sum = 0;
    for (int k = 0; k < length; ++k) sum += darkness(l, k);
    if (sum > best) {
      best = sum;
      darkest = l;
    }
  }
  return darkest;
}

bool overlap(const Word& a, const Word& b, double margin) {
  return a.xMin + margin < b.xMax && b.xMin + margin < a.xMax && a.yMin + margin < b.yMax &&
         b.yMin + margin < a.yMax;
}

// For every pixel that is on, the length of the run of pixels on through it along its line: `lines` lines of
// `length` pixels, pixel k of line l at index(l, k).
template <typename Index>
void runLengths(const std::vector<unsigned char>& on, int lines, int length, Index index,
                std::vector<int>& runs) {
  for (int l = 0; l < lines; ++l)
    for (int k = 0; k < length;) {
      int end = k;
      while (end < length && on[index(l, end)]) ++end;
      for (int j = k; j < end; ++j) runs[index(l, j)] = end - k;
      k = end == k ? k + 1 : end;
    }
}

}  // namespace

std::string missingVectorRenderers() {
  std::string missing;
  for (const char* tool : {"rsvg-convert", "pdftoppm", "pdftotext"})
    if (runCommand(std::string("command -v ") + tool) != 0)
      missing += std::string(missing.empty() ? "" : ", ") + tool;
  return missing;
}

RenderedChart renderChart(const std::string& path, int page) {
  RenderedChart chart;
  const std::string stem = path + ".rendered";
  std::string pdf = path, log;
  if (fs::path(path).extension() == ".svg") {
    pdf = stem + ".pdf";
    if (runCommand(
            "rsvg-convert -f pdf --dpi-x 72 --dpi-y 72 -o " + shellQuoted(pdf) + " " + shellQuoted(path),
            &log) != 0) {
      chart.error = "rsvg-convert cannot draw " + path + ": " + log;
      return chart;
    }
  }
  const std::string pageOption = " -f " + std::to_string(page) + " -l " + std::to_string(page) + " ";
  if (runCommand("pdftoppm -r 72 -singlefile" + pageOption + shellQuoted(pdf) + " " + shellQuoted(stem),
                 &log) != 0 ||
      !readPpm(stem + ".ppm", chart)) {
    chart.error = "pdftoppm cannot draw page " + std::to_string(page) + " of " + pdf + ": " + log;
    return chart;
  }
  std::string words;
  if (runCommand("pdftotext -bbox" + pageOption + shellQuoted(pdf) + " -", &words) != 0) {
    chart.error = "pdftotext cannot read " + pdf + ": " + words;
    return chart;
  }
  chart.words = readWords(words);
  return chart;
}

RenderedChart crop(const RenderedChart& chart, double x0, double y0, double x1, double y1) {
  RenderedChart part;
  const int left = std::clamp(static_cast<int>(x0), 0, chart.width),
            right = std::clamp(static_cast<int>(x1), left, chart.width);
  const int top = std::clamp(static_cast<int>(y0), 0, chart.height),
            bottom = std::clamp(static_cast<int>(y1), top, chart.height);
  part.width = right - left;
  part.height = bottom - top;
  for (int y = top; y < bottom; ++y) {
    const auto row = chart.rgb.begin() + (static_cast<std::ptrdiff_t>(y) * chart.width + left) * 3;
    part.rgb.insert(part.rgb.end(), row, row + static_cast<std::ptrdiff_t>(part.width) * 3);
  }
  for (Word w : chart.words)
    if (w.xMin >= left && w.xMax <= right && w.yMin >= top && w.yMax <= bottom) {
      w.xMin -= left, w.xMax -= left, w.yMin -= top, w.yMax -= top;
      part.words.push_back(w);
    }
  return part;
}

Stroke measureStroke(const RenderedChart& chart, std::array<int, 3> colour, int tolerance) {
  const int w = chart.width, h = chart.height;
  std::vector<unsigned char> on(static_cast<std::size_t>(w) * h, 0);
  for (std::size_t p = 0; p < on.size(); ++p) {
    bool near = true;
    for (int c = 0; c < 3; ++c) near = near && std::abs(chart.rgb[3 * p + c] - colour[c]) <= tolerance;
    on[p] = near;
  }
  // Run lengths through every pixel of the curve, along rows and along columns.
  std::vector<int> across(on.size(), 0), down(on.size(), 0);
  runLengths(
      on, h, w, [w](int y, int x) { return static_cast<std::size_t>(y) * w + x; }, across);
  runLengths(
      on, w, h, [w](int x, int y) { return static_cast<std::size_t>(y) * w + x; }, down);
  std::vector<int> shorter;
  for (std::size_t p = 0; p < on.size(); ++p)
    if (on[p]) shorter.push_back(std::min(across[p], down[p]));
  Stroke stroke;
  stroke.pixels = static_cast<long>(shorter.size());
  if (shorter.empty()) return stroke;
  std::nth_element(shorter.begin(), shorter.begin() + shorter.size() / 2, shorter.end());
  stroke.width = shorter[shorter.size() / 2];
  return stroke;
}

std::vector<std::string> invalidTextAnchors(const std::string& svgText) {
  std::vector<std::string> invalid;
  const std::regex anchor("text-anchor\\s*[=:]\\s*\"?([A-Za-z-]+)");
  for (std::sregex_iterator it(svgText.begin(), svgText.end(), anchor), end; it != end; ++it) {
    const std::string value = (*it)[1];
    if (value != "start" && value != "middle" && value != "end") invalid.push_back(value);
  }
  return invalid;
}

std::vector<std::string> misplacedText(const RenderedChart& chart, const std::vector<std::string>& titles) {
  std::vector<std::string> problems;
  if (chart.width == 0) return {"nothing was drawn"};
  // The axis lines are the darkest column (left axis) and row (bottom axis): the grid is light grey, text
  // and curves cover little of any one column or row.
  const int axisX =
      darkestLine(chart.width, chart.height, [&](int x, int y) { return darkness(chart, x, y); });
  const int axisY =
      darkestLine(chart.height, chart.width, [&](int y, int x) { return darkness(chart, x, y); });
  const std::regex number("(-|\\+|\u2212)?([0-9]+(\\.[0-9]*)?|\\.[0-9]+)([eE][-+]?[0-9]+)?%?");
  const std::set<std::string> titleWords(titles.begin(), titles.end());
  for (const Word& label : chart.words) {
    if (!std::regex_match(label.text, number)) continue;
    const double x0 = label.xMin + 0.5, x1 = label.xMax - 0.5, y0 = label.yMin + 0.5, y1 = label.yMax - 0.5;
    if (y1 < axisY && x0 < axisX && x1 > axisX)
      problems.push_back("tick label '" + label.text +
                         "' runs across the left axis (x = " + std::to_string(axisX) + ")");
    if (x0 > axisX && y0 < axisY && y1 > axisY)
      problems.push_back("tick label '" + label.text +
                         "' runs across the bottom axis (y = " + std::to_string(axisY) + ")");
    for (const Word& title : chart.words)
      if (titleWords.count(title.text) && overlap(label, title, kTouching))
        problems.push_back("tick label '" + label.text + "' lies under the axis title's '" + title.text +
                           "'");
  }
  return problems;
}

void expectReadableChart(const std::string& path, const std::vector<std::string>& titleWords, int curves) {
  SCOPED_TRACE(path);
  if (fs::path(path).extension() == ".svg") {
    std::ifstream in(path, std::ios::binary);
    std::stringstream svg;
    svg << in.rdbuf();
    for (const std::string& anchor : invalidTextAnchors(svg.str()))
      ADD_FAILURE() << "text-anchor=\"" << anchor << "\" is not SVG";
  }
  const RenderedChart chart = renderChart(path);
  ASSERT_TRUE(chart.error.empty()) << chart.error;
  const std::array<int, 3> colours[2] = {{230, 159, 0}, {86, 180, 233}};
  for (int k = 0; k < std::min(curves, 2); ++k) {
    const Stroke stroke = measureStroke(chart, colours[k]);
    EXPECT_GT(stroke.pixels, 200) << "curve " << k + 1 << " is not drawn";
    EXPECT_LE(stroke.width, kThinLine) << "curve " << k + 1 << " is a band " << stroke.width
                                       << " pixels wide (" << stroke.pixels << " pixels of its colour)";
  }
  for (const std::string& problem : misplacedText(chart, titleWords)) ADD_FAILURE() << problem;
  EXPECT_EQ(measureStroke(chart, kStrayRed).pixels, 0) << "a red box the chart does not draw";
}

}  // namespace rt::test
