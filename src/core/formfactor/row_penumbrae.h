// The blocks that cannot hide anything of a pair, ruled out before the pair is prepared, from regions made
// once per row.
//
// A matrix is computed row by row: element e fixed, the other element o running over the rest. By the
// symmetry of PenumbraRegion's argument (a segment from e to o meets the block either way round), every
// point of o's plane that a closed convex block hides from some point of e lies in the convex hull of the
// projections of the block's corners from e's corners onto that plane. That region depends on e, the block
// and o's plane only, so along a row it is made once per plane (six in a room) and reused for hundreds of
// pairs; an o outside it sees all of e past the block. In a room with blocks more than half of the pairs
// the shaft test lets through are ruled out this way, each with a few 2D cross products, where preparing
// them for clipping costs the block's faces, its region from o's corners, and the hull of the two.
#pragma once

#include <vector>

#include "core/formfactor/penumbra_region.h"
#include "core/formfactor/solid_silhouette.h"
#include "core/vec.h"

namespace rt {

// Per thread; keeps the regions of one row element at a time.
class RowPenumbrae {
 public:
  // `shapes`: the closed convex solids; `eps`: a length, 1e-10 of the scene's size say (larger is safer:
  // fewer blocks ruled out).
  RowPenumbrae(const std::vector<SolidShape>& shapes, double eps) : shapes_(&shapes), eps_(eps) {}

  // True when `solid` hides nothing between the row's element (its corners `rowCorners`, element id
  // `rowElement`) and the polygon `other` lying in the plane (origin, unit normal), with the row's element
  // in front of that plane.
  bool rulesOut(int rowElement, const Vec3* rowCorners, int rowCount, int solid, const Vec3* other,
                int otherCount, const Vec3& origin, const Vec3& normal);

 private:
  struct Entry {
    int solid = -1;
    Vec3 normal = Vec3::Zero();
    double offset = 0;
    bool bounded = false;
    PenumbraRegion region;
  };
  const std::vector<SolidShape>* shapes_;
  double eps_;
  int rowElement_ = -1;
  std::vector<Entry> entries_;
};

}  // namespace rt
