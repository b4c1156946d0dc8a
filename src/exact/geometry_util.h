// Small double-precision helpers shared by the plain parts of the exact library (clipping, bounds, scales).
#pragma once

#include <Eigen/Geometry>

#include "core/vec.h"

namespace rt::exact {

// Keeps the part of a convex polygon with normal . (p - point) >= 0 (Sutherland-Hodgman; points on the plane
// kept).
Polygon clipToHalfspace(const Polygon& polygon, const Vec3& point, const Vec3& normal);
// The same into `out`, reusing its storage (the hot loops of the point evaluator allocate nothing).
void clipToHalfspace(const Polygon& polygon, const Vec3& point, const Vec3& normal, Polygon& out);

// Lambert's contour sum -(1/2pi) sum_k beta_k n . gamma_k without a facing test (lambert.cpp): callers that
// know the polygon faces x skip recomputing its normal.
double lambertContourSum(const Vec3& x, const Vec3& n, const Polygon& contour);

Eigen::AlignedBox3d boundsOf(const Polygon& polygon);

// Signed distances of the polygon's vertices from the plane through `point` with unit `normal`: {min, max}.
std::pair<double, double> distanceRange(const Polygon& polygon, const Vec3& point, const Vec3& normal);

}  // namespace rt::exact
