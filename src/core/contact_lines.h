// Contact lines: where one surface stands on another (a block on the floor, a box against a wall), the
// lower surface is lit on one side of the line and sees only the block's inside on the other. An element
// that straddles the line averages the two, and on the Cornell box such floor elements carry most of the
// error of the floor's irradiance. Cutting each patch along the edges of other patches that lie in its plane
// and cross its interior gives elements that are each wholly on one side.
#pragma once

#include <vector>

#include "core/scene.h"

namespace rt {

// The edges of other patches (not parallel to it) lying in patch `index`'s plane within `tolerance`, clipped
// to the patch, that cross its interior (edges along its boundary, such as a wall meeting the floor at the
// floor's edge, cut nothing). Each as its two end points.
std::vector<std::pair<Vec3, Vec3>> contactSegments(const Scene& scene, int index, double tolerance);

// Patch `index` cut along its contact segments into convex pieces, counter-clockwise about its normal like
// the patch. A segment cuts only the pieces it crosses, along its whole line through them, so the pieces stay
// convex. One piece, the patch itself, when nothing stands on it.
std::vector<Polygon> cutAtContacts(const Scene& scene, int index, double tolerance);

}  // namespace rt
