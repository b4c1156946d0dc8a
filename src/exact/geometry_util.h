// Small double-precision helpers shared by the plain parts of the exact library (bounds, scales).
#pragma once

#include <Eigen/Geometry>

#include "core/geometry/plane_clip.h"
#include "core/vec.h"

namespace rt::exact {

// (The half-space clip these parts use is core/geometry/plane_clip.h's clipToHalfspace.)

// Lambert's contour sum -(1/2pi) sum_k beta_k n . gamma_k without a facing test (lambert.cpp): callers that
// know the polygon faces x skip recomputing its normal.
double lambertContourSum(const Vec3& x, const Vec3& n, const Polygon& contour);

Eigen::AlignedBox3d boundsOf(const Polygon& polygon);

// Signed distances of the polygon's vertices from the plane through `point` with unit `normal`: {min, max}.
std::pair<double, double> distanceRange(const Polygon& polygon, const Vec3& point, const Vec3& normal);

}  // namespace rt::exact
