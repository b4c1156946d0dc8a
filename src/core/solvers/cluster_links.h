// The links of hierarchical radiosity with clustering and the oracle that makes them. Refinement starts
// with the root gathering from itself and works top-down: a pair of nodes (receiver R, source S) becomes a
// link when the most light it could carry is small, otherwise the larger node (by bounding sphere) is
// split and its children are tried against the other.
//
// The oracle (Smits, Arvo & Greenberg 1994) bounds K_RS, the irradiance at R per unit radiosity of S:
//   K+ = A_S cos+_S cos+_R / (pi d_min^2),  d_min = distance of the centroids minus both sphere radii,
// with cos+ = 1 for a cluster (any orientation may face the other) and, for an element, the largest cosine
// between its normal and a direction that reaches the other's sphere. Visibility is unknown to the bound, so
// the true K lies in [0, K+] and a link can miss up to rho_R B_S K+ of R's radiosity; the pair is linked
// when that is at most `threshold` (brightness-weighted: B_S is the source's current area-mean
// radiosity, rho_R the receiver's largest reflectance), or when both are elements, which cannot be split.
// Nodes whose spheres overlap are split without a bound.
//
// What a link stores is the geometric part of the transfer, K ~ V x cos+_R / d^2 (x A_S cos_S / pi for a
// source element), and the direction u from the receiver's centroid to the source's: clusters are
// orientation-aware through normal classes (cluster_directions.h; Sillion 1995 uses a directional
// distribution of the same kind), which turn the direction into what a source cluster radiates towards the
// receiver and what each element of a receiver cluster gets. An element that receives directly uses its
// own cosine. Element pairs closer than twice their radii get the exact
// unoccluded polygon-to-polygon form factor, others the centroid's point-to-polygon one. The visible
// fraction V comes from a few rays between random points (area-weighted elements of a cluster, uniform
// points on them); a link that no ray passes is dropped.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/formfactor/ray_scene.h"
#include "core/solvers/cluster_tree.h"

namespace rt {

struct ClusterLink {
  int receiver;        // node index that gathers
  int source;          // node index gathered from
  float K;             // the geometric part of the transfer (see above)
  float direction[3];  // unit, from the receiver's centroid towards the source's
};

struct LinkRefinement {
  // Link when rho_R * brightness[S] * K+ <= threshold (radiosity units).
  double threshold = 0;
  int visibilityRays = 4;
  std::uint64_t seed = 1;
};

// The links for the whole scene, sorted by receiver then source (the same for a seed at any thread count).
// brightness: per node, its area-mean radiosity (largest channel) as currently known. rays: visibility rays
// cast are added to it.
std::vector<ClusterLink> refineLinks(const ClusterTree& tree, const Mesh& mesh, const RayScene& scene,
                                     const std::vector<double>& brightness, const LinkRefinement& options,
                                     std::atomic<long>& rays);

}  // namespace rt
