// Small double-precision helpers shared by the plain parts of the exact library (clipping, bounds, scales).
#pragma once

#include <Eigen/Geometry>

#include "core/vec.h"

namespace rt::exact {

// Keeps the part of a convex polygon with normal . (p - point) >= 0 (Sutherland-Hodgman; points on the plane
// kept).
Polygon clipToHalfspace(const Polygon& polygon, const Vec3& point, const Vec3& normal);

Eigen::AlignedBox3d boundsOf(const Polygon& polygon);

// Signed distances of the polygon's vertices from the plane through `point` with unit `normal`: {min, max}.
std::pair<double, double> distanceRange(const Polygon& polygon, const Vec3& point, const Vec3& normal);

}  // namespace rt::exact
