// Radiometry of single patches seen from a point: the solid angle a planar polygon subtends (exactly, and by
// the small-patch approximation A cos(theta) / r^2 that the definition of solid angle starts from), and the
// projected solid angle of the hemisphere, integral of cos(theta) d(omega) = pi, that turns radiance into
// radiosity (B = pi L). The lesson on measuring light draws and quotes these.
#pragma once

#include "core/vec.h"

namespace rt {

// The solid angle (sr) that `polygon` (planar, convex, either winding) subtends at `point`: the area of its
// central projection onto the unit sphere about the point. Each triangle of a fan from vertex 0 by Van
// Oosterom and Strackee's formula tan(Omega/2) = R1.(R2 x R3) / (r1 r2 r3 + (R1.R2) r3 + (R1.R3) r2 +
// (R2.R3) r1), exact up to rounding at any distance. 0 for a point in the polygon's plane.
double polygonSolidAngle(const Vec3& point, const Polygon& polygon);

// The small-patch approximation A |cos(theta)| / r^2 (sr), with r the distance from `point` to the polygon's
// centroid and theta the angle between the polygon's normal and that line: the definition
// d(omega) = cos(theta) dA / r^2 applied to the whole patch at once. Good when the patch is small against r.
double smallPatchSolidAngle(const Vec3& point, const Polygon& polygon);

// The hemisphere's integral of cos(theta) d(omega), by the midpoint rule over `rings` bands of polar angle
// (d(omega) = sin(theta) d(theta) d(phi); the azimuth integrates exactly to 2 pi). Converges to pi like
// 1/rings^2.
double hemisphereCosineIntegral(int rings);

}  // namespace rt
