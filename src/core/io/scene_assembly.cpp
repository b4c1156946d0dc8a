#include "core/io/scene_assembly.h"

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/polygon.h"
#include "core/polygon_split.h"

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
  // The simplicity test and ear clipping are quadratic in the vertex count: bound it.
  if (polygon.size() > kMaxPolygonVertices)
    throw InputError(where, "polygon has " + std::to_string(polygon.size()) + " vertices; at most " +
                                std::to_string(kMaxPolygonVertices) +
                                " are accepted (split it into smaller polygons)");
  for (std::size_t i = 0; i < polygon.size(); ++i)
    if (!polygon[i].allFinite())
      throw InputError(vertexLocation(where, i), "vertex " + std::to_string(i) +
                                                     " has a coordinate that is not a "
                                                     "finite number (NaN or infinity)");
  for (std::size_t i = 0; i < polygon.size(); ++i)
    if (polygon[i].cwiseAbs().maxCoeff() > kMaxCoordinate)
      throw InputError(vertexLocation(where, i),
                       "vertex " + std::to_string(i) + " has a coordinate of magnitude " +
                           formatNumber(polygon[i].cwiseAbs().maxCoeff()) + ", beyond the " +
                           formatNumber(kMaxCoordinate) +
                           " scene units the geometry can handle (a unit mistake?)");

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

  // Judged on the projection onto the best-fit plane (the Newell normal), so that a slightly twisted quad
  // that looks convex from the front is accepted (and split below).
  const std::vector<Vec2> flat = projectOntoPlane(outline, normal);
  if (const auto crossing = firstCrossingEdges(flat)) {
    const auto edge = [&](int k) {
      return std::to_string(k + 1) + "-" + std::to_string((k + 1) % static_cast<int>(outline.size()) + 1);
    };
    throw InputError(where, "polygon outline crosses itself: its edges between vertices " +
                                edge(crossing->first) + " and " + edge(crossing->second) +
                                " meet (vertices counted from 1)");
  }
  const bool convex = isConvex(outline, normal) &&
                      std::abs(totalTurning(outline, normal) - 2 * std::numbers::pi) <= std::numbers::pi;
  const double deviation = planarityDeviation(outline);
  const double tolerance = kPlanarityTolerance * size;
  if (convex && deviation <= tolerance) {
    scene.patches.push_back(makePatch(outline, surface, where));
    return;
  }

  // Radiosity needs planar convex patches: triangles cover the same outline with such pieces. A fan suits a
  // convex outline; a concave one is ear-clipped. Projecting a non-planar outline onto a plane would move the
  // measured corners instead.
  std::vector<Polygon> triangles;
  if (convex) {
    triangles = fanTriangulate(outline);
  } else {
    const auto ears = earClip(flat);
    if (!ears)
      throw InputError(where,
                       "polygon is not convex and could not be split into triangles (an outline too "
                       "thin for double precision?); split it into convex polygons");
    for (const auto& t : *ears) triangles.push_back({outline[t[0]], outline[t[1]], outline[t[2]]});
  }
  int kept = 0;
  for (const Polygon& triangle : triangles) {
    if (!(polygonArea(triangle) > kZeroAreaTolerance * size * size)) continue;  // collinear corner
    scene.patches.push_back(makePatch(triangle, surface, where));
    ++kept;
  }
  std::string what;
  if (!convex) what = "polygon is not convex (" + std::to_string(outline.size()) + " vertices)";
  if (deviation > tolerance) {
    std::string detail = "its vertices lie up to " + formatNumber(deviation, 3) + " " + scene.unit +
                         " from their best-fit plane";
    if (outline.size() >= 4)
      detail += " (" + formatNumber(deviationFromFirstPlane(outline), 3) + " " + scene.unit +
                " from the plane of the first three)";
    what += (what.empty() ? "polygon" : " and") + std::string(" is not planar: ") + detail +
            ", more than the tolerance " + formatNumber(tolerance, 3) + " " + scene.unit;
  }
  scene.warnings.push_back(where.describe() + ": warning: " + what + "; split into " + std::to_string(kept) +
                           (convex ? " triangles" : " triangles by ear clipping"));
}

namespace {

// True when some point of `to` lies in front of `from`'s plane and some point of `from` in front of `to`'s:
// the two can exchange light (occlusion aside). `eps` is a length below which a point counts as on the plane.
bool canSee(const Patch& from, const Patch& to, double eps) {
  auto anyInFront = [eps](const Patch& plane, const Patch& other) {
    for (const Vec3& v : other.vertices)
      if ((v - plane.vertices[0]).dot(plane.normal) > eps) return true;
    return false;
  };
  return anyInFront(from, to) && anyInFront(to, from);
}

}  // namespace

void addLightWarnings(Scene& scene) {
  const Eigen::AlignedBox3d box = scene.bounds();
  const double eps = 1e-9 * (box.isEmpty() ? 1.0 : box.diagonal().norm());
  std::vector<int> reaches(scene.surfaces.size(), -1);  // per emitting surface: 1 reaches something, 0 not
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    const Patch& light = scene.patches[i];
    if (!scene.materialOf(light).isEmitter()) continue;
    int& state = reaches[light.surface];
    if (state == 1) continue;
    state = 0;
    for (std::size_t j = 0; j < scene.patches.size() && state == 0; ++j)
      if (j != i && canSee(light, scene.patches[j], eps)) state = 1;
  }
  int lights = 0, dark = 0;
  for (std::size_t s = 0; s < reaches.size(); ++s) {
    if (reaches[s] < 0) continue;
    ++lights;
    if (reaches[s] == 1) continue;
    ++dark;
    const Patch* first = nullptr;
    for (const Patch& p : scene.patches)
      if (p.surface == static_cast<int>(s)) {
        first = &p;
        break;
      }
    scene.warnings.push_back(first->origin.describe() + ": warning: light '" + scene.surfaces[s].name +
                             "' faces away from every other surface: its emission reaches nothing (list its "
                             "vertices counter-clockwise seen from the side it lights)");
  }
  if (lights > 0 && dark == lights)
    scene.warnings.push_back(
        SourceLocation{scene.sourceFile}.describe() +
        ": warning: no light reaches any surface: every reflector's radiosity will be 0");
}

}  // namespace rt::io_detail
