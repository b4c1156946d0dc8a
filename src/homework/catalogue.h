// The textbook's form-factor formulas as a student uses them, for the keys: Lambert's point-to-polygon sum
// and two configurations of Howell's catalogue. Written from the formulas, not from the core's methods, so
// that the tests comparing them with the core compare two independent computations.
#pragma once

#include <string>
#include <vector>

#include "core/vec.h"

namespace rt::homework {

// Lambert: F(dA -> polygon) = (1/2pi) sum_k beta_k n . (R_k x R_k+1) / |R_k x R_k+1|, for a polygon wholly in
// front of the point; the sign is made positive (the polygon's orientation does not matter here).
double lambert(const Vec3& x, const Vec3& n, const Polygon& polygon);

// Directly opposed parallel rectangles a x b at distance c (Howell's catalogue, C-11). Appends the worked
// steps (the ratios and every term) to `steps`.
double parallelRectangles(double a, double b, double c, std::vector<std::string>& steps);

// From a w x l rectangle to an h x l rectangle sharing the edge of length l, at a right angle (C-14).
double perpendicularRectangles(double w, double h, double l, std::vector<std::string>& steps);

// (1/A_i) int_{A_i} F(dA -> to) dA over the rectangle [0, l] x [0, w] of the plane z = 0 with `normal`, by a
// 24 x 24 Gauss-Legendre rule graded towards the edge y = 0 (where the integrand's derivative is singular
// when `to` shares that edge).
double integrateLambert(double l, double w, const Vec3& normal, const Polygon& to);

}  // namespace rt::homework
