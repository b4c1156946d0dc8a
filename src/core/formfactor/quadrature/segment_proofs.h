// Proofs about every segment from one convex polygon to another at once (a source and a receiver, or a
// panel of the source and the receiver): that an occluder's face or a closed convex solid cuts them all, or
// that a solid misses them all. Each is decided on finitely many points (corners, corner-to-corner
// crossings), with a margin, so that the pair's form factor is 0, or unoccluded, without clipping.
#pragma once

#include <utility>
#include <vector>

#include "core/vec.h"

namespace rt {

// True when the convex polygon (counter-clockwise about its unit `normal`, its plane normal . p = offset)
// cuts every segment from the convex polygon `from` to the convex polygon `to` with a margin `eps` (a
// length): the two lie strictly on opposite sides of its plane and every corner-to-corner segment crosses it
// strictly inside. Every segment crosses the plane at a point of the convex hull of those crossings, so that
// is enough.
bool polygonCutsEverySegment(const Vec3* from, int fromCount, const Vec3* to, int toCount,
                             const Vec3* polygon, int count, const Vec3& normal, double offset, double eps);

// A closed convex solid (a block with its bottom): the outward planes of its faces (unit normal, offset).
using SolidPlanes = std::vector<std::pair<Vec3, double>>;

// True when the closed convex solid (`centre` inside it) cuts every segment from the convex polygon `from`
// to the convex polygon `to` with a margin `eps`: the crossings of the corner-to-corner segments with one of
// its cross-sections through the centre (across the line of sight, or parallel to a face) all lie inside it.
// Every such segment crosses that plane in the hull of those crossings.
bool solidCutsEverySegment(const Vec3* from, int fromCount, const Vec3* to, int toCount,
                           const SolidPlanes& solid, const Vec3& centre, double eps);

// True when one face plane of the closed convex solid has both polygons strictly in front of it (by more
// than `eps`): every segment from one to the other stays in front of it too, so the solid hides nothing.
bool solidMissesEverySegment(const Vec3* from, int fromCount, const Vec3* to, int toCount,
                             const SolidPlanes& solid, double eps);

// Whether the segment pq passes through the closed convex solid's inside by more than `eps` (each face's
// plane): a pair whose centres' segment does cannot be proven missed, and the proofs are not tried.
bool segmentEntersSolid(const Vec3& p, const Vec3& q, const SolidPlanes& solid, double eps);

// True when a plane through an edge of one polygon and a corner of the other has both polygons on or behind
// it and every corner of the solid strictly in front (by more than `eps`): such a plane is a face of the
// polygons' convex hull, which holds every segment from one to the other, so the solid (the convex hull of
// `corners`) meets none of them. With solidMissesEverySegment() (the solid's own faces) it settles most
// pairs whose blocks have no shadow region (block_shadow_regions.h) before the clipper is prepared.
bool solidOutsideHullOf(const Vec3* a, int na, const Vec3* b, int nb, const Vec3* corners, int cornerCount,
                        double eps);

}  // namespace rt
