#include "homework/figure.h"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace rt::homework {
namespace {

struct Bounds {
  Vec2 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec2 hi = -lo;
};

Bounds boundsOf(const Figure& f) {
  Bounds b;
  auto add = [&](const Vec2& p) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  };
  for (const auto& s : f.shapes)
    for (const Vec2& p : s.points) add(p);
  for (const auto& l : f.labels) add(l.at);
  if (b.lo.x() > b.hi.x()) b = {{0, 0}, {1, 1}};
  return b;
}

std::string fmt(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", v);
  return buffer;
}

std::string escapeXml(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

std::string escapeTex(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '_' || c == '%' || c == '&' || c == '#' || c == '$') out += '\\';
    out += c;
  }
  return out;
}

std::string svgColour(const std::string& fill) {
  if (fill == "grey") return "#bbbbbb";
  if (fill == "light") return "#e8eef8";
  if (fill == "accent") return "#f4a261";
  return "none";
}

}  // namespace

std::string toSvg(const Figure& figure, double widthPixels) {
  const Bounds b = boundsOf(figure);
  const double margin = 40;  // room for labels, which the bounds only count by their anchor
  const double span = std::max(b.hi.x() - b.lo.x(), 1e-9);
  const double scale = (widthPixels - 2 * margin) / span;
  const double height = (b.hi.y() - b.lo.y()) * scale + 2 * margin;
  auto X = [&](const Vec2& p) { return fmt(margin + (p.x() - b.lo.x()) * scale); };
  auto Y = [&](const Vec2& p) { return fmt(height - margin - (p.y() - b.lo.y()) * scale); };
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fmt(widthPixels) + "\" height=\"" +
                    fmt(height) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (const auto& s : figure.shapes) {
    std::string points;
    for (const Vec2& p : s.points) points += X(p) + "," + Y(p) + " ";
    out += std::string("<") + (s.closed ? "polygon" : "polyline") + " points=\"" + points + "\" fill=\"" +
           svgColour(s.fill) + "\" stroke=\"black\" stroke-width=\"1.2\"" +
           (s.dashed ? " stroke-dasharray=\"4 3\"" : "") + "/>\n";
  }
  for (const auto& l : figure.labels)
    out += "<text x=\"" + X(l.at) + "\" y=\"" + Y(l.at) + "\" text-anchor=\"middle\">" + escapeXml(l.text) +
           "</text>\n";
  return out + "</svg>\n";
}

std::string toLatexPicture(const Figure& figure, double widthMm) {
  const Bounds b = boundsOf(figure);
  const double scale = widthMm / std::max(b.hi.x() - b.lo.x(), 1e-9);
  auto P = [&](const Vec2& p) {
    return "(" + fmt((p.x() - b.lo.x()) * scale) + "," + fmt((p.y() - b.lo.y()) * scale) + ")";
  };
  const double height = (b.hi.y() - b.lo.y()) * scale;
  std::string out =
      "\\setlength{\\unitlength}{1mm}\n\\begin{picture}(" + fmt(widthMm) + "," + fmt(height) + ")\n";
  for (const auto& s : figure.shapes) {
    // Filled shapes (the part the exercise is about) are drawn with thick lines: the picture environment
    // cannot fill, and its \line takes only a few slopes, so every segment is a straight \qbezier.
    out += s.fill == "accent" ? "\\thicklines\n" : "\\thinlines\n";
    // Points closer than a millimetre to the last one drawn are merged into the next segment: \qbezier
    // overflows TeX's arithmetic on very short segments.
    const std::size_t count = s.points.size();
    Vec2 last = s.points.front();
    for (std::size_t k = 1; k <= count; ++k) {
      if (k == count && !s.closed) break;
      const Vec2& q = s.points[k % count];
      if ((q - last).norm() * scale < 1.0) continue;
      out += "\\qbezier" + P(last) + P(0.5 * (last + q)) + P(q) + "\n";
      last = q;
    }
  }
  for (const auto& l : figure.labels)
    out += "\\put" + P(l.at) + "{\\makebox(0,0){\\small " + escapeTex(l.text) + "}}\n";
  return out + "\\end{picture}\n";
}

}  // namespace rt::homework
