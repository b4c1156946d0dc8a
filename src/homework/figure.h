// A small 2D drawing (y up) that a handout shows: written once by the generator, rendered as SVG for the
// Markdown handout and as a LaTeX picture for the LaTeX source, so the two never disagree.
#pragma once

#include <string>
#include <vector>

#include "core/vec.h"

namespace rt::homework {

struct Figure {
  struct Shape {
    std::vector<Vec2> points;  // a polyline, or a polygon when closed
    bool closed = false;
    std::string fill;  // "" or a colour name known to both writers: grey, light, accent
    bool dashed = false;
  };
  struct Label {
    Vec2 at;
    std::string text;  // plain text (no maths): both writers escape it
  };
  std::vector<Shape> shapes;
  std::vector<Label> labels;
  std::string caption;

  void line(Vec2 a, Vec2 b, bool dashed = false) { shapes.push_back({{a, b}, false, "", dashed}); }
  void polygon(std::vector<Vec2> points, std::string fill = "") {
    shapes.push_back({std::move(points), true, std::move(fill), false});
  }
  void rect(Vec2 lo, Vec2 hi, std::string fill = "") {
    polygon({lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}}, std::move(fill));
  }
  void label(Vec2 at, std::string text) { labels.push_back({at, std::move(text)}); }
};

// Scaled to `widthPixels` wide, with a margin for labels.
std::string toSvg(const Figure& figure, double widthPixels = 360);
// A LaTeX picture environment (no package needed) scaled to `widthMm` wide.
std::string toLatexPicture(const Figure& figure, double widthMm = 70);

}  // namespace rt::homework
