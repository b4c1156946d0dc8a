// Triangulating a convex planar domain so that given segments become element edges. The exact library
// installs CGAL's constrained Delaunay triangulation and mesher (exact predicates) here; the core keeps a
// simple fallback that cuts the domain along the segments' lines and splits the pieces uniformly (T-vertices
// where cuts end).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/vec.h"

namespace rt {

struct PlanarDomain {
  std::vector<Vec2> boundary;                      // convex, counter-clockwise
  std::vector<std::pair<Vec2, Vec2>> constraints;  // segments inside the boundary (may cross each other)
  double maxEdge = 0;                              // longest triangle edge wanted (0 = no size limit)
};

struct PlanarTriangulation {
  std::vector<Vec2> points;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise
};

using ConstrainedTriangulator = std::function<PlanarTriangulation(const PlanarDomain&)>;

// Installs the triangulator the discontinuity mesher uses (the exact library registers CGAL's). name is
// reported in the statistics.
void setConstrainedTriangulator(ConstrainedTriangulator triangulator, const std::string& name);
// The installed one, or cutConvexDomain.
ConstrainedTriangulator constrainedTriangulator();
std::string constrainedTriangulatorName();

// Fallback: the domain is cut by each constraint's line within the convex cells the segment crosses, then
// every cell is fan-triangulated and each triangle split into k^2 similar ones so that edges stay below
// maxEdge.
PlanarTriangulation cutConvexDomain(const PlanarDomain& domain);

}  // namespace rt
