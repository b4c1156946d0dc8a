#include "core/io/scene_assembly.h"

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/polygon.h"

namespace rt::io_detail {

std::string readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path}, "cannot open the file (missing or not readable)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError({path}, "cannot read the file");
  return text.str();
}

std::string formatNumber(double value, int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << value;
  return out.str();
}

std::string formatRgb(const Rgb& value) {
  return "[" + formatNumber(value[0]) + ", " + formatNumber(value[1]) + ", " + formatNumber(value[2]) + "]";
}

void checkMaterial(const Material& material, const SourceLocation& where) {
  if (material.name.empty()) throw InputError(where, "material has an empty name");
  const std::string who = "material '" + material.name + "'";
  if (!material.reflectance.allFinite())
    throw InputError(where,
                     who + ": reflectance " + formatRgb(material.reflectance) + " is not a finite number");
  if ((material.reflectance < 0.0).any() || (material.reflectance >= 1.0).any())
    throw InputError(where,
                     who + ": reflectance " + formatRgb(material.reflectance) +
                         " is outside [0,1) (a reflectance of 1 or more creates energy; real surfaces stay "
                         "below about 0.95)");
  if (!material.emission.allFinite())
    throw InputError(where, who + ": emission " + formatRgb(material.emission) + " is not a finite number");
  if ((material.emission < 0.0).any())
    throw InputError(
        where, who + ": emission " + formatRgb(material.emission) + " is negative (must be >= 0 W/m^2)");
}

SourceLocation vertexLocation(const SourceLocation& where, std::size_t index) {
  SourceLocation at = where;
  if (!at.jsonPath.empty()) at.jsonPath += "/" + std::to_string(index);
  return at;
}

namespace {

// Drops vertices that repeat their predecessor (closing vertex = first vertex included): exporters often
// write them.
Polygon withoutRepeatedVertices(const Polygon& polygon, double tolerance, int* dropped) {
  Polygon out;
  for (const Vec3& v : polygon)
    if (out.empty() || (v - out.back()).norm() > tolerance) out.push_back(v);
  while (out.size() > 1 && (out.back() - out.front()).norm() <= tolerance) out.pop_back();
  *dropped = static_cast<int>(polygon.size() - out.size());
  return out;
}

double boxDiagonal(const Polygon& polygon) {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : polygon) box.extend(v);
  return box.diagonal().norm();
}

Patch makePatch(const Polygon& vertices, int surface, const SourceLocation& where) {
  Patch patch;
  patch.vertices = vertices;
  const Vec3 n = newellNormal(vertices);
  patch.normal = n.normalized();
  patch.area = 0.5 * n.norm();
  patch.surface = surface;
  patch.origin = where;
  return patch;
}

}  // namespace

void addPolygon(Scene& scene, const Polygon& polygon, int surface, const SourceLocation& where) {
  if (polygon.size() < 3)
    throw InputError(where,
                     "polygon has " + std::to_string(polygon.size()) + " vertices; at least 3 are needed");
  for (std::size_t i = 0; i < polygon.size(); ++i)
    if (!polygon[i].allFinite())
      throw InputError(vertexLocation(where, i), "vertex " + std::to_string(i) +
                                                     " has a coordinate that is not a "
                                                     "finite number (NaN or infinity)");

  int dropped = 0;
  const Polygon outline =
      withoutRepeatedVertices(polygon, kCoincidentTolerance * boxDiagonal(polygon), &dropped);
  if (outline.size() < 3)
    throw InputError(where, "degenerate polygon: only " + std::to_string(outline.size()) +
                                " distinct vertices (at least 3 are needed)");
  if (dropped > 0)
    scene.warnings.push_back(where.describe() + ": warning: " + std::to_string(dropped) +
                             " repeated vertex(es) dropped from the polygon");

  const double size = maxEdgeLength(outline);
  const Vec3 newell = newellNormal(outline);
  const double area = 0.5 * newell.norm();
  if (!(area > kZeroAreaTolerance * size * size))
    throw InputError(where,
                     "degenerate polygon: zero area (collinear vertices, or an outline folded onto itself); "
                     "longest edge " +
                         formatNumber(size) + " " + scene.unit + ", area " + formatNumber(area));
  const Vec3 normal = newell / newell.norm();

  // Convexity is judged about the Newell normal, i.e. on the polygon's projection onto its best-fit plane, so
  // that a slightly twisted quad that looks convex from the front is accepted (and split below).
  if (!isConvex(outline, normal))
    throw InputError(where,
                     "polygon is not convex; split it into convex polygons (each listed counter-clockwise "
                     "seen from the front)");
  const double turning = totalTurning(outline, normal);
  if (std::abs(turning - 2 * std::numbers::pi) > std::numbers::pi)
    throw InputError(where, "polygon outline crosses itself (it winds around " +
                                formatNumber(std::round(turning / (2 * std::numbers::pi))) + " times)");

  const double deviation = planarityDeviation(outline);
  const double tolerance = kPlanarityTolerance * size;
  if (deviation <= tolerance) {
    scene.patches.push_back(makePatch(outline, surface, where));
    return;
  }
  // Not planar: a fan of triangles covers the same outline with planar pieces (valid because the projection
  // is convex). Radiosity needs planar patches; projecting onto a plane would move the measured corners
  // instead.
  int kept = 0;
  for (const Polygon& triangle : fanTriangulate(outline)) {
    if (!(polygonArea(triangle) > kZeroAreaTolerance * size * size)) continue;  // collinear fan corner
    scene.patches.push_back(makePatch(triangle, surface, where));
    ++kept;
  }
  std::string detail = "its vertices lie up to " + formatNumber(deviation, 3) + " " + scene.unit +
                       " from their best-fit plane";
  if (outline.size() >= 4)
    detail += " (" + formatNumber(deviationFromFirstPlane(outline), 3) + " " + scene.unit +
              " from the plane of the first three)";
  scene.warnings.push_back(where.describe() + ": warning: polygon is not planar: " + detail +
                           ", more than the tolerance " + formatNumber(tolerance, 3) + " " + scene.unit +
                           "; split into " + std::to_string(kept) + " triangles");
}

}  // namespace rt::io_detail
