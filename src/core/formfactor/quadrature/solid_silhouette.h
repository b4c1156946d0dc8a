// A closed convex solid seen from a point outside it: the cone of its silhouette.
//
// From x, a convex solid hides exactly the cone over its silhouette, the loop of edges between the faces x
// sees from the front and those it sees from behind. One convex cone of (for a box) four to six planes
// replaces the three front faces' cones that shadow_clipper.h would otherwise cut one after another, with
// the pieces and the Lambert sums each of them leaves. The planes are exact (a cross product of two corner
// directions each), so the hidden part is the same up to rounding.
#pragma once

#include <vector>

#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/vec.h"

namespace rt {

// The faces, corners and edges of a closed convex solid (closed_solids.h finds them).
struct SolidShape {
  struct Edge {
    int a = 0, b = 0;         // corners; a -> b runs counter-clockwise in face `left`
    int left = 0, right = 0;  // faces
  };
  std::vector<Vec3> corners;            // each corner once
  std::vector<std::vector<int>> faces;  // corner indices, counter-clockwise seen from outside
  SolidPlanes planes;                   // per face: outward unit normal, offset
  std::vector<Edge> edges;              // each edge once
  Vec3 centre = Vec3::Zero();           // the mean of the corners: strictly inside
};

// The solids' shapes from the patches' outlines and closedConvexSolids()'s answer (`solidOf`, per patch the
// solid it bounds or -1); faces in patch order.
std::vector<SolidShape> solidShapes(const std::vector<const std::vector<Vec3>*>& outlines,
                                    const std::vector<int>& solidOf, int solidCount);

// A silhouette edge seen from x: its corners (indices into SolidShape::corners) and the inward side plane of
// the cone through x and it (not normalised; the solid in front of it).
struct SilhouetteEdge {
  Vec3 normal;
  int a = 0, b = 0;
};

// The edges of the silhouette from x, into `out`, as silhouetteCone() below counts them.
int silhouetteEdges(const SolidShape& solid, const Vec3& x, double eps, SilhouetteEdge* out, int capacity);

// The inward side planes (through x, not normalised; the solid in front of every one) of the cone from x
// over the solid, into `cone`. Returns their number; 0 when x is not outside the solid (no face seen from
// the front by more than `eps`, a length), -1 when there would be more than `capacity`. A silhouette edge
// in line with x (seen end-on) gives no plane: its neighbours bound the cone there.
int silhouetteCone(const SolidShape& solid, const Vec3& x, double eps, Vec3* cone, int capacity);

}  // namespace rt
