// The ray-casting estimator of one form factor F_ij, shared by the "raycast" matrix method and the row
// provider that shoots without a stored matrix (so the two give the same numbers for a seed).
//
//   F_ij ~ (1/N) sum_k [ F(dA_k -> j) - (1 - V(x_k, y_k)) A_j K(x_k, y_k) ]
//
// with x_k stratified on i, y_k stratified on j (its strata in a random order, independent of x_k's),
// F(dA -> j) Lambert's exact point-to-polygon form factor, K = cos cos / (pi r^2) the point-to-point kernel
// and V the ray-cast visibility of the segment x_k -> y_k. The first term is the unoccluded form factor from
// x_k: exact, so without occluders the estimator is a stratified quadrature of a bounded integrand and
// adjacent elements (where K is singular) cost no variance. The second takes away what occluders hide, with
// the kernel's own weight, so the estimator is unbiased. The simpler F(dA_k -> j) V(x_k, y_k) weights the
// hidden part of j by its area instead and stays ~25 % off next to a block on the floor however many samples
// it takes.
#pragma once

#include <cstdint>

#include "core/formfactor/pair_matrix.h"
#include "core/mesh.h"

namespace rt {

class PairVisibility;

// N = samples (1..1024) sample pairs on i and j; deterministic for (seed, i, j). The value is clamped at 0
// (hidden samples close together can overshoot); needsVisibility false means no ray was cast.
PairResult estimateRaycastPair(const Mesh& mesh, const PairVisibility& visibility, int i, int j, int samples,
                               std::uint64_t seed);

}  // namespace rt
