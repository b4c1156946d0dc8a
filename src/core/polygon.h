// Geometry of single planar polygons: area, normal, planarity, convexity, triangulation. Pure functions.
#pragma once

#include "core/vec.h"

namespace rt {

// Newell's method: robust for any simple polygon, non-planar ones included. Length = twice the area (planar
// case).
Vec3 newellNormal(const Polygon& polygon);
double polygonArea(const Polygon& polygon);
Vec3 polygonCentroid(const Polygon& polygon);  // area centroid
// Largest distance of a vertex from the best-fit plane through the centroid with the Newell normal.
double planarityDeviation(const Polygon& polygon);
// True when every turn has the same sign about the normal (collinear vertices allowed).
bool isConvex(const Polygon& polygon, const Vec3& normal);
// Fan triangulation from vertex 0 (valid for convex polygons); the triangles keep the winding.
std::vector<Polygon> fanTriangulate(const Polygon& polygon);
// Longest edge length.
double maxEdgeLength(const Polygon& polygon);
// Largest distance of a vertex from the plane through the first three vertices that are not collinear: the
// way measured data usually states how far a quad is from planar (the 4th corner's offset). 0 for fewer than
// 4 vertices.
double deviationFromFirstPlane(const Polygon& polygon);
// Sum of the signed turning angles (radians) at every vertex about `normal`, measured in the plane normal to
// it: +2 pi for a simple convex CCW outline, a multiple of 2 pi larger in magnitude for outlines that wind
// around more than once (pentagrams).
double totalTurning(const Polygon& polygon, const Vec3& normal);

}  // namespace rt
