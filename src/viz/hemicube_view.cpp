#include "viz/hemicube_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>

namespace rt::viz {
namespace {

constexpr Rgb8 kNothing{235, 235, 235};
constexpr Rgb8 kBackFace{90, 90, 90};  // the back of a polygon: blocks, receives nothing
const char* kFaceNames[5] = {"top", "+u", "+v", "-u", "-v"};

// One past the largest element id in the buffers: the room a row summed from them needs, whatever element
// count the caller gave.
std::size_t seenElements(const HemicubeFaces& faces) {
  int largest = -1;
  for (const HemicubeFaceBuffer& face : faces.faces)
    for (int id : face.element) largest = std::max(largest, id);
  return static_cast<std::size_t>(largest + 1);
}

}  // namespace

HemicubeColouring hemicubeColouringFromName(const std::string& name) {
  if (name == "delta") return HemicubeColouring::DeltaFormFactors;
  if (name == "items") return HemicubeColouring::ItemBuffer;
  throw std::invalid_argument("unknown hemicube colouring '" + name + "' (delta, items)");
}

std::array<Vec3, 4> hemicubePixelCorners(HemicubeFace face, int row, int column, int resolution) {
  const HemicubeFaceAxes axes = hemicubeFaceAxes(face);
  const int height = face == HemicubeFace::Top ? resolution : hemicubeSideRows(resolution);
  const double du = 2.0 / resolution, dv = (1.0 - axes.upMin) / height;
  const double a0 = -1 + column * du, a1 = a0 + du, b0 = axes.upMin + row * dv, b1 = b0 + dv;
  auto corner = [&](double a, double b) { return Vec3(a * axes.across + b * axes.up + axes.forward); };
  return {corner(a0, b0), corner(a1, b0), corner(a1, b1), corner(a0, b1)};
}

Vec2 unfoldHemicubePoint(HemicubeFace face, const Vec3& p) {
  // Points on the shared edge of two sides belong to both: the face decides where they go.
  switch (face) {
    case HemicubeFace::Top:
      return {p.x(), p.y()};
    case HemicubeFace::PlusU:
      return {2 - p.z(), p.y()};
    case HemicubeFace::MinusU:
      return {-2 + p.z(), p.y()};
    case HemicubeFace::PlusV:
      return {p.x(), 2 - p.z()};
    case HemicubeFace::MinusV:
      return {p.x(), -2 + p.z()};
  }
  return {p.x(), p.y()};
}

Drawing hemicubeFacesDrawing(const HemicubeFaces& faces, std::size_t elements,
                             const HemicubeViewOptions& options) {
  if (faces.resolution < 2) throw std::invalid_argument("the hemicube view needs rendered faces");
  Drawing d;
  d.width = options.size.width;
  d.height = options.size.height;
  const double font = std::max(11.0, 0.024 * d.height * options.size.fontScale());
  const double legendWidth = 15 * font, top = 3.5 * font, margin = 1.0 * font;
  const double side = std::max(40.0, std::min(d.width - legendWidth - 2 * margin, d.height - top - margin));
  const double unit = side / 4.0;
  const Vec2 centre(margin + side / 2, margin + side / 2 + (d.height - top - margin - side) / 2);
  auto toFigure = [&](HemicubeFace face, const Vec3& local) {
    return Vec2(centre + unit * unfoldHemicubePoint(face, local));
  };

  const double maxDelta = maxDeltaFormFactor(faces.resolution);

  for (int f = 0; f < 5; ++f) {
    const auto face = static_cast<HemicubeFace>(f);
    const auto& buffer = faces.faces[static_cast<std::size_t>(f)];
    const std::vector<double>& deltas = deltaFormFactors(faces.resolution, face);
    for (int row = 0; row < buffer.height; ++row)
      for (int column = 0; column < buffer.width; ++column) {
        const std::size_t p = static_cast<std::size_t>(row) * buffer.width + column;
        Rgb8 colour;
        if (options.colouring == HemicubeColouring::DeltaFormFactors)
          colour = sampleColourMap(options.map, deltas[p] / maxDelta);
        else
          colour = buffer.element[p] >= 0                       ? categoryColour(buffer.element[p])
                   : buffer.element[p] == kHemicubeSeesBackFace ? kBackFace
                                                                : kNothing;
        std::vector<Vec2> quad;
        for (const Vec3& corner : hemicubePixelCorners(face, row, column, faces.resolution))
          quad.push_back(toFigure(face, corner));
        d.polygon(quad, colour);
      }
    // Face outline and name.
    const auto first = hemicubePixelCorners(face, 0, 0, faces.resolution);
    const auto last = hemicubePixelCorners(face, buffer.height - 1, buffer.width - 1, faces.resolution);
    Vec2 lo = toFigure(face, first[0]), hi = lo;
    for (const Vec3& c : {first[0], first[1], first[2], first[3], last[0], last[1], last[2], last[3]}) {
      lo = lo.cwiseMin(toFigure(face, c));
      hi = hi.cwiseMax(toFigure(face, c));
    }
    d.outline({{lo.x(), lo.y()}, {hi.x(), lo.y()}, {hi.x(), hi.y()}, {lo.x(), hi.y()}},
              std::max(1.0, 1.5 * options.size.fontScale()), {30, 30, 30});
    d.rectangle(lo.x() + 0.2 * font, hi.y() - 1.3 * font, 2.2 * font, 1.1 * font, {255, 255, 255}, 1.0,
                {30, 30, 30});
    d.text(kFaceNames[f], {lo.x() + 1.3 * font, hi.y() - 0.75 * font}, 0.8 * font, Drawing::Align::Centre,
           Drawing::Align::Centre, {20, 20, 20}, true);
  }

  std::string title = options.title;
  if (title.empty())
    title = "Hemicube of element " + std::to_string(faces.element) + " (" + std::to_string(faces.resolution) +
            "x" + std::to_string(faces.resolution) + "): " +
            (options.colouring == HemicubeColouring::ItemBuffer ? "item buffer" : "delta form factors");
  d.text(title, {0.5 * d.width, d.height - 0.4 * font}, 1.15 * font, Drawing::Align::Centre,
         Drawing::Align::End, {10, 10, 10}, true);

  const double legendX = margin + side + 1.5 * font;
  if (options.colouring == HemicubeColouring::DeltaFormFactors) {
    drawColourBar(d, legendX, centre.y() - 0.35 * side, 1.3 * font, 0.7 * side, options.map, 0.0, maxDelta,
                  false, "delta F", 0.8 * font);
    return d;
  }
  // Item buffer legend: the elements seen, largest form factor first.
  std::vector<double> row(std::max(elements, seenElements(faces)), 0.0);
  accumulateHemicubeRow(faces, row.data());
  row.resize(elements);
  std::vector<int> order(row.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return row[a] > row[b]; });
  double y = d.height - top - 0.5 * font;
  d.text("element: F (sum of its pixels)", {legendX, y}, 0.85 * font, Drawing::Align::Start,
         Drawing::Align::End, {20, 20, 20}, true);
  y -= 1.8 * font;
  int shown = 0;
  for (int j : order) {
    if (row[j] <= 0 || shown >= options.legendEntries) break;
    d.rectangle(legendX, y - 0.5 * font, 1.1 * font, 1.1 * font, categoryColour(j), 1.0, {40, 40, 40});
    char text[64];
    std::snprintf(text, sizeof text, "%d: %.4f", j, row[j]);
    d.text(text, {legendX + 1.6 * font, y}, 0.85 * font, Drawing::Align::Start, Drawing::Align::Centre);
    y -= 1.6 * font;
    ++shown;
  }
  const bool anyBackFace = std::any_of(faces.faces.begin(), faces.faces.end(), [](const auto& buffer) {
    return std::find(buffer.element.begin(), buffer.element.end(), kHemicubeSeesBackFace) !=
           buffer.element.end();
  });
  if (anyBackFace) {
    d.rectangle(legendX, y - 0.5 * font, 1.1 * font, 1.1 * font, kBackFace, 1.0, {40, 40, 40});
    d.text("back of a surface (blocks)", {legendX + 1.6 * font, y}, 0.85 * font, Drawing::Align::Start,
           Drawing::Align::Centre);
    y -= 1.6 * font;
  }
  d.rectangle(legendX, y - 0.5 * font, 1.1 * font, 1.1 * font, kNothing, 1.0, {40, 40, 40});
  d.text("nothing seen", {legendX + 1.6 * font, y}, 0.85 * font, Drawing::Align::Start,
         Drawing::Align::Centre);
  char total[64];
  std::snprintf(total, sizeof total, "sum of all: %.4f", std::accumulate(row.begin(), row.end(), 0.0));
  d.text(total, {legendX, y - 2.0 * font}, 0.85 * font, Drawing::Align::Start, Drawing::Align::Centre);
  return d;
}
}  // namespace rt::viz
