// The occluders of one pair as they block light: the shaft's candidate elements merged per patch, and
// without a polygon that another one in the same plane covers.
//
// Why merging is exact: a patch is a planar convex polygon, and so the convex hull of some of its elements
// lies inside it. Every point of that hull is opaque scene geometry, so using the hull in place of the
// elements blocks no ray the scene lets through; it blocks every ray the elements block. What changes is the
// cost: a 40-gon cap meshed as 38 fan triangles casts one shadow instead of 38, and the point evaluator's
// work grows with the number of shadows it cuts out of the receiver. A polygon lying inside another one of
// the same plane (the two coincident polygons of a two-sided disc, back to back) casts a shadow inside the
// other's, so it is left out.
#pragma once

#include <vector>

#include "core/mesh.h"

namespace rt::exact {

// `occluders`: candidate elements of `mesh` (as setUpPair finds them), `polygons` their polygons in the
// same order. Returns the blocking polygons: one per patch (the hull of its candidates' corners, counter-
// clockwise seen from the patch's front), none inside another coplanar one (within `eps`, a length).
std::vector<Polygon> mergeOccluders(const Mesh& mesh, const std::vector<int>& occluders,
                                    const std::vector<Polygon>& polygons, double eps);

}  // namespace rt::exact
