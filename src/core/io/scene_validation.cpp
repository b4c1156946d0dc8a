// The invariants every loader guarantees, checked again on a finished Scene (also useful for scenes built in
// code).
#include <cmath>
#include <numbers>

#include "core/io/scene_assembly.h"
#include "core/io/scene_loader.h"
#include "core/polygon.h"

namespace rt {
namespace {

using io_detail::formatNumber;

void checkPatch(const Scene& scene, std::size_t index) {
  const Patch& patch = scene.patches[index];
  const SourceLocation where = patch.origin.file.empty() && patch.origin.jsonPath.empty()
                                   ? SourceLocation{scene.sourceFile, 0, ""}
                                   : patch.origin;
  const std::string who = "patch " + std::to_string(index);
  if (patch.surface < 0 || patch.surface >= static_cast<int>(scene.surfaces.size()))
    throw InputError(where,
                     who + " refers to surface " + std::to_string(patch.surface) + ", which does not exist");
  const std::string what = who + " (surface '" + scene.surfaces[patch.surface].name + "')";
  const Polygon& v = patch.vertices;
  if (v.size() < 3) throw InputError(where, what + " has fewer than 3 vertices");
  for (const Vec3& p : v)
    if (!p.allFinite())
      throw InputError(where, what + " has a coordinate that is not a finite number (NaN or infinity)");
  for (const Vec3& p : v)
    if (p.cwiseAbs().maxCoeff() > io_detail::kMaxCoordinate)
      throw InputError(where, what + " has a coordinate beyond " + formatNumber(io_detail::kMaxCoordinate));
  const double size = maxEdgeLength(v);
  const Vec3 newell = newellNormal(v);
  const double area = 0.5 * newell.norm();
  if (!(area > io_detail::kZeroAreaTolerance * size * size))
    throw InputError(where, what + " is degenerate: zero area (collinear or coincident vertices)");
  const Vec3 normal = newell / newell.norm();
  const double deviation = planarityDeviation(v);
  if (deviation > io_detail::kPlanarityTolerance * size)
    throw InputError(where, what + " is not planar: a vertex lies " + formatNumber(deviation) + " " +
                                scene.unit + " from the best-fit plane");
  if (!isConvex(v, normal) || std::abs(totalTurning(v, normal) - 2 * std::numbers::pi) > std::numbers::pi)
    throw InputError(where, what + " is not convex");
  if (!patch.normal.allFinite() || std::abs(patch.normal.norm() - 1) > 1e-9 ||
      patch.normal.dot(normal) < 1 - 1e-9)
    throw InputError(
        where, what + ": stored normal does not match the vertex order (expected the unit Newell normal)");
  if (!(std::abs(patch.area - area) <= 1e-9 * area))
    throw InputError(where, what + ": stored area " + formatNumber(patch.area) +
                                " differs from the polygon's area " + formatNumber(area));
}

}  // namespace

void validateScene(const Scene& scene) {
  const SourceLocation file{scene.sourceFile, 0, ""};
  for (const Material& m : scene.materials) io_detail::checkMaterial(m, file);
  for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
    const Surface& s = scene.surfaces[i];
    if (s.material < 0 || s.material >= static_cast<int>(scene.materials.size()))
      throw InputError(file, "surface '" + s.name + "' refers to material " + std::to_string(s.material) +
                                 ", which does not exist");
  }
  if (scene.patches.empty()) throw InputError(file, "the scene has no polygons");
  for (std::size_t i = 0; i < scene.patches.size(); ++i) checkPatch(scene, i);
}

void requireLight(const Scene& scene) {
  if (scene.hasEmitter()) return;
  throw InputError({scene.sourceFile, 0, ""},
                   "no light: none of the " + std::to_string(scene.patches.size()) +
                       " patches has a material with positive emission, so every radiosity would be 0 "
                       "(give a material an emission > 0 and use it on a surface; form factors and the "
                       "matrix F need no light)");
}

}  // namespace rt
