// A 2D figure as a plain list of shapes (polygons, polylines, text) in pixel coordinates, origin bottom-left.
// The matrix, hemicube-face and Nusselt-disk views build one of these without VTK (so tests can check what is
// drawn); writeDrawing paints it through VTK's context 2D API, which exports true vectors to SVG and PDF.
#pragma once

#include <string>
#include <vector>

#include "viz/colour_map.h"
#include "viz/figure_output.h"

namespace rt::viz {

struct Drawing {
  enum class Kind { Polygon, Polyline, Text, Image };
  enum class Align { Start, Centre, End };
  struct Shape {
    Kind kind = Kind::Polygon;
    std::vector<Vec2> points;  // Text: one point, the anchor
    bool filled = true;
    Rgb8 fill{255, 255, 255};
    Rgb8 stroke{0, 0, 0};
    double strokeWidth = 0;  // 0: no outline
    std::string text;
    double fontSize = 14;
    Align hAlign = Align::Start, vAlign = Align::Start;  // vertical: Start = bottom
    double angleDegrees = 0;
    bool bold = false;
    // Image: pixels (top row first) of pixelsWide x pixelsHigh, stretched over points[0] (bottom-left) to
    // points[1] (top-right), each pixel a sharp square.
    std::vector<Rgb8> pixels;
    int pixelsWide = 0, pixelsHigh = 0;
  };

  double width = 800, height = 600;
  Rgb8 background{255, 255, 255};
  std::vector<Shape> shapes;

  void polygon(std::vector<Vec2> points, Rgb8 fill, double strokeWidth = 0, Rgb8 stroke = {0, 0, 0});
  void outline(std::vector<Vec2> points, double strokeWidth, Rgb8 stroke, bool closed = true);
  void rectangle(double x, double y, double w, double h, Rgb8 fill, double strokeWidth = 0,
                 Rgb8 stroke = {0, 0, 0});
  void line(Vec2 a, Vec2 b, double strokeWidth, Rgb8 stroke);
  void text(const std::string& text, Vec2 anchor, double fontSize, Align hAlign = Align::Start,
            Align vAlign = Align::Start, Rgb8 colour = {20, 20, 20}, bool bold = false,
            double angleDegrees = 0);
  void image(double x, double y, double w, double h, int pixelsWide, int pixelsHigh,
             std::vector<Rgb8> pixels);
  // A circle as a polygon with enough segments to look round at any print size.
  void circle(Vec2 centre, double radius, Rgb8 fill, bool filled, double strokeWidth, Rgb8 stroke);

  std::size_t count(Kind kind) const;
};

// A vertical colour bar in [x, x+w] x [y, y+h] with `ticks` labels on its right (log10 spacing when
// logScale).
void drawColourBar(Drawing& drawing, double x, double y, double w, double h, ColourMap map, double min,
                   double max, bool logScale, const std::string& title, double fontSize);

// Formats a value for a label: 3 significant digits, scientific notation outside [1e-3, 1e4).
std::string formatValue(double value);

// PNG (raster), SVG and PDF (vectors). Needs an X server (VTK's context rendering). Throws
// std::runtime_error.
void writeDrawing(const Drawing& drawing, const std::string& path);

}  // namespace rt::viz
