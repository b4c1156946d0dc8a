// The two properties every physical BRDF has, measured numerically: energy conservation (the directional
// albedo, the fraction of light from one direction reflected into the whole hemisphere, is at most 1) and
// Helmholtz reciprocity (f_r(w_i, w_o) = f_r(w_o, w_i)). The lessons quote them and the tests check every
// model against them.
#pragma once

#include <cstdint>

#include "core/brdf.h"

namespace rt {

// The directional albedo a(w_i) = integral over the hemisphere of f_r(w_i, w_o) cos(theta_o) d(omega_o), plus
// the delta part, by the midpoint rule over `rings` bands of theta_o and `sectors` of phi_o
// (d(omega) = sin(theta) d(theta) d(phi)). Lambertian: rho exactly, whatever w_i.
double directionalAlbedo(const Brdf& brdf, const Vec3& wi, int rings = 256, int sectors = 512);

// The largest directional albedo over incidence angles 0, 1, ..., 89 degrees in the x-z plane and in the
// y-z plane (an anisotropic lobe differs between them).
double largestAlbedo(const Brdf& brdf, int rings = 128, int sectors = 256);

// The largest relative asymmetry |f(w_i, w_o) - f(w_o, w_i)| / max(f(w_i, w_o), f(w_o, w_i)) over `pairs`
// random pairs of directions in the upper hemisphere (0 for a reciprocal model, up to rounding).
double reciprocityError(const Brdf& brdf, int pairs = 10000, std::uint64_t seed = 1);

}  // namespace rt
