#include "viz/visibility_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/polygon.h"

namespace rt::viz {

Drawing visibilityDrawing(const VisibilityRegions& r, const VisibilityViewOptions& options) {
  Drawing d;
  d.width = options.size.width;
  d.height = options.size.height;
  const double font = std::max(11.0, 0.026 * d.height * options.size.fontScale());
  std::string title = options.title;
  if (title.empty())
    title = "Exact visibility: element " + std::to_string(r.receiver) + " seen from a point of element " +
            std::to_string(r.source);
  d.text(title, {0.5 * d.width, d.height - 0.4 * font}, 1.1 * font, Drawing::Align::Centre,
         Drawing::Align::End, {10, 10, 10}, true);
  char line[160];
  std::snprintf(line, sizeof line, "F(point -> visible part) = %.6f    unoccluded = %.6f", r.formFactor,
                r.unoccludedFormFactor);
  d.text(line, {0.5 * d.width, 0.8 * font}, font, Drawing::Align::Centre, Drawing::Align::Start);
  if (r.receiverOutline.size() < 3) {
    d.text("the receiver is behind the point's horizon: nothing is visible", {0.5 * d.width, 0.5 * d.height},
           font, Drawing::Align::Centre, Drawing::Align::Centre);
    return d;
  }

  // A frame in the receiver's plane: first edge along x.
  const Vec3 origin = polygonCentroid(r.receiverOutline);
  const Vec3 normal = newellNormal(r.receiverOutline).normalized();
  const Vec3 ex = (r.receiverOutline[1] - r.receiverOutline[0]).normalized();
  const Vec3 ey = normal.cross(ex);
  auto planar = [&](const Vec3& p) { return Vec2((p - origin).dot(ex), (p - origin).dot(ey)); };
  Eigen::AlignedBox2d box;
  for (const Vec3& p : r.receiverOutline) box.extend(planar(p));
  const double top = 2.6 * font, bottom = 3.2 * font, margin = 1.5 * font, legend = 12 * font;
  const double scale = std::min((d.width - 2 * margin - legend) / std::max(box.sizes().x(), 1e-12),
                                (d.height - top - bottom) / std::max(box.sizes().y(), 1e-12));
  const Vec2 offset(margin + 0.5 * (d.width - 2 * margin - legend) - scale * box.center().x(),
                    bottom + 0.5 * (d.height - top - bottom) - scale * box.center().y());
  auto toFigure = [&](const Polygon& polygon) {
    std::vector<Vec2> out;
    for (const Vec3& p : polygon) out.push_back(offset + scale * planar(p));
    return out;
  };
  auto clipToBox =
      [&](std::vector<Vec2> points) {  // shadows may reach past the receiver: keep the figure tidy
        const Vec2 lo = offset + scale * box.min(), hi = offset + scale * box.max();
        for (Vec2& p : points) p = p.cwiseMax(lo).cwiseMin(hi);
        return points;
      };

  const Rgb8 visibleColour{86, 180, 233}, shadowColour{90, 90, 96}, edge{0, 114, 178};
  const double stroke = std::max(1.0, 2.0 * options.size.fontScale());
  // The visible part is the receiver minus the shadows; painting the receiver and then the (convex) shadows
  // over it gives the same picture without filling non-convex polygons.
  d.polygon(toFigure(r.receiverOutline), visibleColour);
  for (const Polygon& shadow : r.shadows)
    if (shadow.size() >= 3) d.polygon(clipToBox(toFigure(shadow)), shadowColour);
  for (const auto& [outer, holes] : r.visible) {
    if (outer.size() >= 3) d.outline(toFigure(outer), stroke, edge);
    for (const Polygon& hole : holes)
      if (hole.size() >= 3) d.outline(toFigure(hole), stroke, {213, 94, 0});
  }
  d.outline(toFigure(r.receiverOutline), stroke, {20, 20, 20});

  const double x = d.width - legend + 0.5 * font;
  double y = d.height - top - font;
  d.rectangle(x, y - 0.55 * font, 1.1 * font, 1.1 * font, visibleColour, 1.0, {40, 40, 40});
  d.text("visible", {x + 1.6 * font, y}, 0.85 * font, Drawing::Align::Start, Drawing::Align::Centre);
  y -= 1.7 * font;
  d.rectangle(x, y - 0.55 * font, 1.1 * font, 1.1 * font, shadowColour, 1.0, {40, 40, 40});
  std::snprintf(line, sizeof line, "shadows (%zu)", r.shadows.size());
  d.text(line, {x + 1.6 * font, y}, 0.85 * font, Drawing::Align::Start, Drawing::Align::Centre);
  y -= 1.7 * font;
  std::string owners = "occluders:";
  for (std::size_t k = 0; k < r.shadowOwners.size() && k < 8; ++k)
    owners += " " + std::to_string(r.shadowOwners[k]);
  if (!r.shadowOwners.empty())
    d.text(owners, {x, y}, 0.8 * font, Drawing::Align::Start, Drawing::Align::Centre);
  return d;
}

void writeVisibilityFigure(const VisibilityRegions& regions, const VisibilityViewOptions& options,
                           const std::string& path) {
  writeDrawing(visibilityDrawing(regions, options), path);
}

}  // namespace rt::viz
