// Splitting polygons that are not patches yet: a concave (simple) outline becomes triangles by ear clipping,
// and an outline that crosses itself is found and named. Models exported by modelling tools contain both:
// an L-shaped floor as one n-gon, or a bow tie from a vertex order mistake. Pure functions.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "core/vec.h"

namespace rt {

// The outline projected onto the plane normal to `normal` (any length > 0), in a frame whose (x, y) turn
// counter-clockwise about `normal`: a polygon listed counter-clockwise seen from the front stays so.
std::vector<Vec2> projectOntoPlane(const Polygon& polygon, const Vec3& normal);

// Two edges (k, k+1) and (m, m+1) of the 2D outline that are not neighbours and touch or cross, or nullopt
// for a simple outline. O(n^2): callers bound n.
std::optional<std::pair<int, int>> firstCrossingEdges(const std::vector<Vec2>& outline);

// Ear clipping of a simple counter-clockwise 2D outline: triangles as index triples into the outline, in the
// outline's winding. Collinear vertices are clipped without a triangle (they add no area). nullopt when no
// ear is found (an outline that is not simple, or one too thin for double precision).
std::optional<std::vector<std::array<int, 3>>> earClip(const std::vector<Vec2>& outline);

}  // namespace rt
