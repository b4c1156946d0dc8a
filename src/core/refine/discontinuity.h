// Shadow boundaries of area lights: the critical lines where a receiver's view of a light changes topology.
// A VE surface is the wedge swept by rays from a light vertex through an occluder edge; an EV surface the
// wedge swept by rays from a light edge through an occluder vertex. Where those wedges cut a receiver lie the
// umbra and penumbra boundaries (and the other radiance discontinuities inside the penumbra). Heckbert 1992;
// Lischinski et al. 1992.
#pragma once

#include <vector>

#include "core/scene.h"

namespace rt {

struct CriticalSegment {
  enum class Kind { VE, EV };
  Vec3 a, b;          // on the receiver's plane, clipped to the receiver polygon
  int receiver = -1;  // patch indices in the scene
  int light = -1;
  int occluder = -1;
  Kind kind = Kind::VE;
  // The light lies wholly on one side of the critical plane: the line bounds the umbra or the penumbra rather
  // than separating two penumbra regions.
  bool extremal = false;
};

// Critical segments on one receiver patch, for every emitting patch and every other patch as occluder.
// Occluder edges shared by two patches (closed solids) count only where they are silhouettes from the light
// vertex, occluder vertices only where the critical plane supports the occluder. Coincident segments are
// reported once. Segments shorter than minLength are dropped. (Not handled: EEE surfaces, and wedges blocked
// by a third object.)
std::vector<CriticalSegment> criticalSegments(const Scene& scene, int receiver, double minLength);

// All receivers.
std::vector<CriticalSegment> criticalSegments(const Scene& scene, double minLength);

// Clips the segment a-b to a convex planar polygon (CCW about `normal`); false when nothing is left.
bool clipSegmentToPolygon(Vec3& a, Vec3& b, const Polygon& polygon, const Vec3& normal);

}  // namespace rt
