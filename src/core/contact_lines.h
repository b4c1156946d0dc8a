// Contact lines: where one surface stands on another (a block on the floor, a box against a wall), the
// lower surface is lit on one side of the line and sees only the block's inside on the other. An element
// that straddles the line averages the two, and on the Cornell box such floor elements carry most of the
// error of the floor's irradiance. Cutting each patch along the edges of other patches that lie in its plane
// and cross its interior gives elements that are each wholly on one side.
//
// Near-coplanar overlaps are the same thing seen face on: a patch parallel to another and a little in front
// of it (a light hung just below an uncut ceiling, a picture on a wall, a rug on a floor) covers part of it,
// and that part sees only the back of the patch in front. The covered patch is cut along the front patch's
// outline, projected onto its plane, so that the covered part becomes elements of its own.
#pragma once

#include <vector>

#include "core/scene.h"

namespace rt {

// One line a patch is cut along, and why.
struct CutSegment {
  Vec3 a, b;             // end points, in the patch's plane and strictly inside it
  int other = -1;        // the patch whose edge it is
  bool overlap = false;  // false: a contact (the other stands on the patch); true: the other lies in front
  double gap = 0;        // overlap: how far in front of the patch's plane the other lies (scene units)
};

// The edges of other patches that cut patch `index`, clipped to the patch and crossing its interior (edges
// along its boundary, such as a wall meeting the floor at the floor's edge, cut nothing):
// - contacts: edges of patches not parallel to it that lie in its plane within `tolerance`;
// - overlaps (when overlapGap > 0): the edges of patches parallel to it whose every vertex lies in front of
//   its plane by at most overlapGap (or in it, within tolerance), projected onto its plane.
std::vector<CutSegment> cutSegments(const Scene& scene, int index, double tolerance, double overlapGap = 0);
// The contacts alone, each as its two end points.
std::vector<std::pair<Vec3, Vec3>> contactSegments(const Scene& scene, int index, double tolerance);

// Patch `index` cut along its cut segments into convex pieces, counter-clockwise about its normal like
// the patch. A segment cuts only the pieces it crosses, along its whole line through them, so the pieces stay
// convex. One piece, the patch itself, when nothing stands on it or lies in front of it.
std::vector<Polygon> cutAtContacts(const Scene& scene, int index, double tolerance, double overlapGap = 0);

}  // namespace rt
