#include "viz/nusselt_view.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/formfactor/analytic.h"
#include "core/formfactor/nusselt.h"

namespace rt::viz {

NusseltConstruction nusseltConstruction(const Vec3& point, const Vec3& normal, const Polygon& receiver,
                                        int samplesPerEdge) {
  if (receiver.size() < 3)
    throw std::invalid_argument("the Nusselt construction needs a polygon with 3+ vertices");
  if (normal.norm() < 1e-12) throw std::invalid_argument("the Nusselt construction needs a non-zero normal");
  NusseltConstruction c;
  c.point = point;
  c.normal = normal.normalized();
  // Any axis not parallel to the normal gives the base plane's u.
  const Vec3 helper = std::abs(c.normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  c.u = (helper - c.normal * helper.dot(c.normal)).normalized();
  c.v = c.normal.cross(c.u);
  c.receiver = receiver;
  c.visible = clipPolygonToPlane(receiver, point, c.normal);
  c.exact = pointToPolygonFormFactor(point, c.normal, receiver);
  if (c.visible.size() < 3) return c;
  // The projection itself is core's (the computation the lessons run); this keeps the outlines for drawing.
  const NusseltProjection projection = nusseltProject(point, c.normal, receiver, std::max(1, samplesPerEdge));
  if (projection.diskOutline.size() >= 3) {
    c.u = projection.u;
    c.v = projection.v;
  }
  c.onHemisphere = projection.sphereOutline;
  c.onDisk = projection.diskOutline;
  c.diskAreaFraction = projection.formFactor;
  return c;
}

Drawing nusseltDiskDrawing(const NusseltConstruction& c, const NusseltViewOptions& options) {
  Drawing d;
  d.width = options.size.width;
  d.height = options.size.height;
  const double font = std::max(11.0, 0.03 * d.height * options.size.fontScale());
  const double radius = 0.36 * std::min(d.width, d.height);
  const Vec2 centre(0.5 * d.width, 0.47 * d.height);
  const double stroke = std::max(1.0, 2.0 * options.size.fontScale());

  d.circle(centre, radius, {236, 236, 240}, true, stroke, {60, 60, 60});
  // Axes of the base plane, light, for orientation.
  d.line({centre.x() - radius, centre.y()}, {centre.x() + radius, centre.y()}, 1.0, {170, 170, 170});
  d.line({centre.x(), centre.y() - radius}, {centre.x(), centre.y() + radius}, 1.0, {170, 170, 170});
  if (c.onDisk.size() >= 3) {
    std::vector<Vec2> region;
    for (const Vec2& p : c.onDisk) region.push_back(centre + radius * p);
    d.polygon(region, {86, 180, 233}, stroke, {0, 114, 178});  // Okabe-Ito sky blue, blue outline
  }
  d.circle(centre, 0.012 * radius, {20, 20, 20}, true, 0, {20, 20, 20});

  char line[160];
  d.text(options.title, {0.5 * d.width, d.height - 0.5 * font}, 1.15 * font, Drawing::Align::Centre,
         Drawing::Align::End, {10, 10, 10}, true);
  d.text("receiver projected on the hemisphere, then on the base disk",
         {0.5 * d.width, d.height - 2.0 * font}, 0.8 * font, Drawing::Align::Centre, Drawing::Align::End);
  std::snprintf(line, sizeof line, "projected area / pi = %.6f", c.diskAreaFraction);
  d.text(line, {0.5 * d.width, 2.3 * font}, font, Drawing::Align::Centre, Drawing::Align::Start);
  std::snprintf(line, sizeof line, "exact form factor (contour integral) = %.6f", c.exact);
  d.text(line, {0.5 * d.width, 0.8 * font}, font, Drawing::Align::Centre, Drawing::Align::Start);
  return d;
}

void writeNusseltDiskFigure(const NusseltConstruction& construction, const NusseltViewOptions& options,
                            const std::string& path) {
  writeDrawing(nusseltDiskDrawing(construction, options), path);
}

}  // namespace rt::viz
