// A chart written as SVG or PDF, as an independent renderer draws it: rsvg-convert (librsvg) reads the SVG,
// pdftoppm and pdftotext (poppler) rasterise the PDF and place its words. What a reader would see wrong is
// measured there: a curve stroked as a band instead of a line, text anchored where SVG has no such anchor,
// tick labels run over their axis or under an axis title.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace rt::test {

// What is missing of rsvg-convert, pdftoppm and pdftotext (empty: all are there).
std::string missingVectorRenderers();

struct Word {
  std::string text;
  double xMin = 0, yMin = 0, xMax = 0, yMax = 0;  // page points, y down
};

// One page of a chart drawn by the renderers at one pixel per point (an SVG's pixel is a point).
struct RenderedChart {
  std::string error;  // why it could not be drawn (empty when it was)
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  std::vector<Word> words;
};

// `path` is .svg (rsvg-convert writes it as PDF at 72 dpi first) or .pdf; `page` counts from 1.
RenderedChart renderChart(const std::string& path, int page = 1);

// The part of `chart` inside the box (page points), its words those inside it, all moved to its corner: one
// figure of a page of the book.
RenderedChart crop(const RenderedChart& chart, double x0, double y0, double x1, double y1);

// The pixels of one curve (within `tolerance` of its colour in every channel): how many, and the median over
// them of the shorter of the horizontal and vertical runs of such pixels through each. For a line that is
// its stroke width (at most 1.5 times it where the line is slanted); a filled band gives its width, tens or
// hundreds of pixels.
struct Stroke {
  long pixels = 0;
  double width = 0;
};
Stroke measureStroke(const RenderedChart& chart, std::array<int, 3> colour, int tolerance = 40);

// The text-anchor values of an SVG's text that SVG does not define (it has start, middle and end).
std::vector<std::string> invalidTextAnchors(const std::string& svgText);

// What a reader would see wrong with the chart's words: a tick label (a number) across the left or bottom
// axis line, or over a word of an axis title (`titles`: the axis titles, split into words where they
// contain spaces). Empty when nothing.
std::vector<std::string> misplacedText(const RenderedChart& chart, const std::vector<std::string>& titles);

// Pure red, which no figure uses (its vermillion is (213, 94, 0)): VTK's PDF device strokes it around text it
// takes for MathText.
inline constexpr std::array<int, 3> kStrayRed{255, 0, 0};

// GoogleTest expectations on the chart in `path` (.svg or .pdf) with `curves` series drawn by writeLineChart
// (its first colours: Okabe-Ito orange, then sky blue): valid anchors (SVG), every curve drawn and a thin
// line (at most kThinLine pixels for the 2.5-pixel pen at 96 dpi), no misplacedText, nothing in kStrayRed.
inline constexpr double kThinLine = 6.0;
void expectReadableChart(const std::string& path, const std::vector<std::string>& titleWords, int curves);

}  // namespace rt::test

// In a GoogleTest body: skip when a renderer is missing.
#define RT_REQUIRE_VECTOR_RENDERERS()                                                           \
  do {                                                                                          \
    if (const std::string missing = rt::test::missingVectorRenderers(); !missing.empty())       \
      GTEST_SKIP() << "needs " << missing << " (librsvg2-bin, poppler-utils: install-deps.sh)"; \
  } while (0)
