// Exact, unoccluded form factors of planar convex polygons: the building blocks of the "analytic" method, the
// lessons and the exact reference.
//
//   point -> polygon:    Lambert's contour formula  F = (1/2pi) sum_k beta_k cos(gamma_k)
//   polygon -> polygon:  Stokes' double contour integral  A_i F_ij = (1/2pi) oint oint ln r  dr_i . dr_j
//
// Both first clip against the other side's plane (horizon clipping): the part of a one-sided polygon that
// lies behind the other's plane exchanges nothing, and the contour formulas are only valid where both cosines
// are >= 0.
#pragma once

#include "core/vec.h"

namespace rt {

// The part of `polygon` on the front side of the plane through `origin` with normal `normal` (points with
// normal . (x - origin) >= 0). Vertices within a relative 1e-12 of the plane count as on it. Convex in,
// convex out; empty when nothing is in front.
Polygon clipPolygonToPlane(const Polygon& polygon, const Vec3& origin, const Vec3& normal);

// Form factor from a differential area at `point` facing `normal` (unit) to `polygon` (CCW seen from its
// front). Zero when the point is behind the polygon's plane; the part of the polygon behind the point's
// tangent plane is clipped away first.
double pointToPolygonFormFactor(const Vec3& point, const Vec3& normal, const Polygon& polygon);

// Lambert's sum without any clipping or facing test: (1/2pi) sum_k theta_k n . (R_k x R_k+1)/|R_k x R_k+1|,
// with the sign such that a polygon facing the point gives a positive value. Also the area of the polygon's
// Nusselt projection on the unit disk divided by pi.
double lambertContourSum(const Vec3& point, const Vec3& normal, const Polygon& polygon);
double lambertContourSum(const Vec3& point, const Vec3& normal, const Vec3* polygon, int count);

// F_ij from polygon i to polygon j (both CCW seen from their fronts), unoccluded, horizon-clipped.
double polygonToPolygonFormFactor(const Polygon& from, const Polygon& to);

// A_i F_ij = (1/2pi) oint oint ln r dr_i . dr_j for two polygons that are already horizon-clipped (each
// entirely on the front side of the other's plane). Edge pairs: closed form for parallel edges (including
// shared, collinear edges), Gauss-Legendre over one edge with the closed-form inner integral over the other
// otherwise, split at the points of closest approach and geometrically graded towards them so that touching
// edges keep full accuracy.
double contourFormFactorArea(const Polygon& from, const Polygon& to);

// The point-to-point kernel cos θ_x cos θ_y / (π r²) between x (normal nx) and y (normal ny), zero where
// either faces away; the integrand of F_ij times A_j.
double pointToPointKernel(const Vec3& x, const Vec3& nx, const Vec3& y, const Vec3& ny);

// Allocation-free overloads on raw vertex arrays (the matrix builders call these once per pair).
double pointToPolygonFormFactor(const Vec3& point, const Vec3& normal, const Vec3* polygon, int count);
double polygonToPolygonFormFactor(const Vec3* from, int fromCount, const Vec3* to, int toCount);

}  // namespace rt
