// The Nusselt analog, computed literally: the (horizon-clipped) polygon is projected centrally onto the unit
// hemisphere around the point (edges become great-circle arcs), then orthographically onto the base disk; the
// fraction of the disk's area it covers is the point-to-polygon form factor. The outline is sampled along
// each arc, so the area converges to Lambert's exact value like 1 / segments^2; the outlines are exposed for
// figures.
#pragma once

#include <vector>

#include "core/vec.h"

namespace rt {

struct NusseltProjection {
  Vec3 u, v;                        // in-plane axes of the disk (right-handed with the normal)
  std::vector<Vec3> sphereOutline;  // points on the unit hemisphere (relative to the point), closed loop
  std::vector<Vec2> diskOutline;    // the same, dropped onto the disk: (u, v) coordinates in the unit disk
  double diskArea = 0;              // shoelace area of diskOutline
  double formFactor = 0;            // diskArea / pi
};

// `segmentsPerEdge` >= 1 points per arc. Empty outline (F = 0) when the polygon is behind the point's tangent
// plane or the point is behind the polygon.
NusseltProjection nusseltProject(const Vec3& point, const Vec3& normal, const Polygon& polygon,
                                 int segmentsPerEdge);

// Just the number: the same computation without keeping the outline.
double nusseltFormFactor(const Vec3& point, const Vec3& normal, const Vec3* polygon, int count,
                         int segmentsPerEdge);

}  // namespace rt
