#include "viz/drawing.h"

#include <cmath>
#include <cstdio>

namespace rt::viz {

void Drawing::polygon(std::vector<Vec2> points, Rgb8 fill, double strokeWidth, Rgb8 stroke) {
  Shape s;
  s.kind = Kind::Polygon;
  s.points = std::move(points);
  s.fill = fill;
  s.strokeWidth = strokeWidth;
  s.stroke = stroke;
  shapes.push_back(std::move(s));
}

void Drawing::outline(std::vector<Vec2> points, double strokeWidth, Rgb8 stroke, bool closed) {
  if (closed && !points.empty()) points.push_back(points.front());
  Shape s;
  s.kind = Kind::Polyline;
  s.points = std::move(points);
  s.filled = false;
  s.strokeWidth = strokeWidth;
  s.stroke = stroke;
  shapes.push_back(std::move(s));
}

void Drawing::rectangle(double x, double y, double w, double h, Rgb8 fill, double strokeWidth, Rgb8 stroke) {
  polygon({{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}}, fill, strokeWidth, stroke);
}

void Drawing::image(double x, double y, double w, double h, int pixelsWide, int pixelsHigh,
                    std::vector<Rgb8> pixels) {
  Shape s;
  s.kind = Kind::Image;
  s.points = {Vec2(x, y), Vec2(x + w, y + h)};
  s.pixelsWide = pixelsWide;
  s.pixelsHigh = pixelsHigh;
  s.pixels = std::move(pixels);
  shapes.push_back(std::move(s));
}

void Drawing::line(Vec2 a, Vec2 b, double strokeWidth, Rgb8 stroke) {
  outline({a, b}, strokeWidth, stroke, false);
}

void Drawing::text(const std::string& content, Vec2 anchor, double fontSize, Align hAlign, Align vAlign,
                   Rgb8 colour, bool bold, double angleDegrees) {
  Shape s;
  s.kind = Kind::Text;
  s.points = {anchor};
  s.text = content;
  s.fontSize = fontSize;
  s.hAlign = hAlign;
  s.vAlign = vAlign;
  s.fill = colour;
  s.bold = bold;
  s.angleDegrees = angleDegrees;
  shapes.push_back(std::move(s));
}

void Drawing::circle(Vec2 centre, double radius, Rgb8 fill, bool filled, double strokeWidth, Rgb8 stroke) {
  std::vector<Vec2> points;
  const int segments = 180;
  for (int k = 0; k < segments; ++k) {
    const double a = 2.0 * M_PI * k / segments;
    points.emplace_back(centre.x() + radius * std::cos(a), centre.y() + radius * std::sin(a));
  }
  if (filled)
    polygon(points, fill, strokeWidth, stroke);
  else
    outline(points, strokeWidth, stroke);
}

std::size_t Drawing::count(Kind kind) const {
  std::size_t n = 0;
  for (const Shape& s : shapes) n += s.kind == kind ? 1 : 0;
  return n;
}

std::string formatValue(double value) {
  char buffer[32];
  const double magnitude = std::abs(value);
  if (value == 0)
    return "0";
  else if (magnitude >= 1e-3 && magnitude < 1e4)
    std::snprintf(buffer, sizeof buffer, "%.3g", value);
  else
    std::snprintf(buffer, sizeof buffer, "%.2e", value);
  return buffer;
}

void drawColourBar(Drawing& drawing, double x, double y, double w, double h, ColourMap map, double min,
                   double max, bool logScale, const std::string& title, double fontSize) {
  const int steps = 96;
  for (int k = 0; k < steps; ++k)
    drawing.rectangle(x, y + h * k / steps, w, h / steps + 0.5, sampleColourMap(map, (k + 0.5) / steps));
  drawing.outline({{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}}, 1.0, {40, 40, 40});
  auto label = [&](double t, double value) {
    const double ty = y + t * h;
    drawing.line({x + w, ty}, {x + w + 0.25 * w, ty}, 1.0, {40, 40, 40});
    drawing.text(formatValue(value), {x + 1.4 * w, ty}, fontSize, Drawing::Align::Start,
                 Drawing::Align::Centre);
  };
  if (logScale && min > 0 && max > min) {
    const double lo = std::log10(min), hi = std::log10(max);
    const int first = static_cast<int>(std::ceil(lo - 1e-9)), last = static_cast<int>(std::floor(hi + 1e-9));
    const int stride = std::max(1, (last - first + 1) / 6 + ((last - first + 1) % 6 ? 1 : 0));
    for (int d = first; d <= last; d += stride) label((d - lo) / (hi - lo), std::pow(10.0, d));
    if (last < first) {
      label(0, min);
      label(1, max);
    }
  } else {
    for (int k = 0; k <= 4; ++k) label(k / 4.0, min + (max - min) * k / 4.0);
  }
  drawing.text(title, {x + 0.5 * w, y + h + 0.9 * fontSize}, fontSize, Drawing::Align::Centre,
               Drawing::Align::Start, {20, 20, 20}, true);
}

}  // namespace rt::viz
