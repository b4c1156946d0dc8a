// The hull planes of two convex polygons, shared by the shadow clipper (shadow_clipper.cpp) and the proofs
// about every segment between two polygons (segment_proofs.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/formfactor/quadrature/shadow_clipper.h"

namespace rt::shadow_detail {

// The faces of the convex hull of two convex polygons other than their own planes each hold an edge of one
// and a corner of the other. Calls visit(p, n, margin2) for every plane through an edge of `edges` (p its
// first corner) and a corner of `others`, n its normal unnormalised and margin2 = eps^2 |n|^2 (a height d is
// beyond eps when d^2 > margin2: no square root for the many planes rejected), until visit returns true;
// returns whether it did. All of `edges` lies on the side of its own centre of each such plane.
template <class Visit>
bool forEachEdgeCornerPlane(const Vec3* edges, int ne, const Vec3* others, int no, double eps,
                            Visit&& visit) {
  for (int e = 0; e < ne; ++e) {
    const Vec3& p = edges[e];
    const Vec3 edge = edges[(e + 1) % ne] - p;
    for (int k = 0; k < no; ++k) {
      const Vec3 n = edge.cross(others[k] - p);
      const double length2 = n.squaredNorm();
      if (!(length2 > 0)) continue;
      if (visit(p, n, eps * eps * length2)) return true;
    }
  }
  return false;
}

}  // namespace rt::shadow_detail
