// Hierarchical radiosity with clustering (Smits, Arvo & Greenberg 1994; Sillion 1995): links between nodes
// of a cluster hierarchy over the elements (cluster_tree.h) replace the n^2 element pairs, refined top-down
// from the root gathering from itself by a brightness-weighted bound on what each link can carry
// (cluster_links.h). No form factor matrix is stored: memory is the tree (2n - 1 nodes) and the links,
// whose count grows about like n at a fixed link tolerance.
//
// Solving gathers along the links (every node gathers irradiance from its sources' current radiosities),
// then push-pulls: a node's irradiance, kept per normal class on a cluster (cluster_directions.h), is
// added to all the elements below it, each taking its own class's; each element's radiosity is E + rho x
// its irradiance, and a cluster's radiosity is the area-weighted mean of its children's. Jacobi sweeps
// until the relative change is at most options.tolerance.
//
// Two refinement rounds: the first with threshold clusterTolerance x the scene's mean radiosity, the
// brightness guessed as E + rho x the ambient term (Cohen et al. 1988); the second with the first's
// radiosities as brightness and a threshold four times smaller, solved from the first's solution. The
// second round's solution is returned. Its error estimate, per element and channel, is
//   2 |B_second - B_first| + (q / (1 - q)) max |last sweep's change| + 2^-24 max |B - E| / (1 - q),
// q = largest reflectance: twice the change from a four times tighter tolerance, the Jacobi tail bound of
// the iteration error, and the rounding of the links' float transfers.
// If the error falls like tolerance^p, |B_second - B_first| >= (4^p - 1) x the second's error, so twice
// the change covers it for p >= 0.29 (measured on the museum and the factory: p about 0.5 to 1). The
// record's standardError is its area-weighted RMS relative to that of B.
#pragma once

#include "core/solvers/solver.h"

namespace rt {

// system.mesh is required (InvalidInput without it); system.F is never read. errorEstimate (optional):
// per-element estimate of |B - exact| (n x 3), as above.
SolverStatus hierarchicalClustering(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                                    const IterationSink& sink = {}, RgbField* errorEstimate = nullptr);

// The cluster tolerance when options.clusterTolerance is 0.
double defaultClusterTolerance();

}  // namespace rt
