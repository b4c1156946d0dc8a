// Hand-built scenes for the exact reference's tests: polygons -> rt::Scene -> buildMesh.
#pragma once

#include <vector>

#include "core/mesh.h"
#include "core/scene.h"

namespace rt::exact::test {

// One patch per polygon (CCW seen from its front), all sharing one grey material.
Scene sceneFromPolygons(const std::vector<Polygon>& polygons);
Mesh meshFromPolygons(const std::vector<Polygon>& polygons, int subdivide = 1);

// Axis-aligned rectangle in the plane coordinate `axis` = `at`, spanning [lo, hi] in the other two
// coordinates, facing +axis (facePositive) or -axis.
Polygon axisRectangle(int axis, double at, const Vec3& lo, const Vec3& hi, bool facePositive);
// The five visible faces of a box [lo, hi] (bottom face omitted when `withBottom` is false), facing outwards.
std::vector<Polygon> boxFaces(const Vec3& lo, const Vec3& hi, bool withBottom);
// The six faces of the room [lo, hi], facing inwards.
std::vector<Polygon> roomFaces(const Vec3& lo, const Vec3& hi);

}  // namespace rt::exact::test
