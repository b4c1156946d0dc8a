// The kernel integrals of the linear basis (linear_basis.h), by point collocation at the nodes: the residual
// of the integral equation vanishes at every node v, which gathers from node w
//
//   K_vw = int phi_w(y) cos(theta_v) cos(theta_y) V(v,y) / (pi r^2) dA_y,
//
// so that b_v = E_v + rho_v sum_w K_vw b_w has the shape of the classic system: K >= 0, and each row sums to
// the form factor from the node to the whole scene (the shape functions add up to 1 everywhere), 1 in a
// closed scene, so every solver that reads a matrix solves it. The nodes' weights A_v = int phi_v dA stand
// for the areas where power is counted.
//
// The integral over one element, the point-to-element form factor weighted by the element's shape
// functions, takes its total from Lambert's exact contour formula (analytic.h) and splits it among the shape
// functions by a Gauss rule over the element whose order grows as the point nears the element; near the
// element the order doubles until no share changes by more than the tolerance. Occluded pairs (the shaft
// test, shaft_culling.h) trace one ray per rule point.
#pragma once

#include <functional>

#include "core/basis/linear_basis.h"
#include "core/formfactor/formfactor_matrix.h"
#include "core/formfactor/formfactor_method.h"

namespace rt {

// The default absolute tolerance of one weighted point-to-element form factor.
inline constexpr double kLinearKernelTolerance = 1e-4;

// int_f phi_b(y) cos cos V / (pi r^2) dA_y for each corner b of element f, seen from `point` facing `normal`:
// shares[b], summing to Lambert's form factor of f times the visible fraction. `visible` (may be empty)
// says whether the segment from the point to y is clear. Returns the Gauss order used per direction.
struct WeightedFormFactor {
  double shares[4] = {0, 0, 0, 0};
  int count = 0;
  double total = 0;  // the unoccluded point-to-element form factor (Lambert)
  int order = 0;
  std::size_t rays = 0;
};
WeightedFormFactor weightedPointFormFactor(const Vec3& point, const Vec3& normal, const Mesh& mesh,
                                           int element, double tolerance,
                                           const std::function<bool(const Vec3&)>& visible = {});

// K for the basis's nodes (m x m). options.tolerance is the weighted form factors' tolerance (0: the
// default); stats counts Lambert evaluations, rays and pairs. May throw Cancelled.
FormFactorMatrix linearKernelMatrix(const Mesh& mesh, const LinearBasis& basis,
                                    const FormFactorOptions& options, Progress& progress,
                                    FormFactorStats& stats);

}  // namespace rt
