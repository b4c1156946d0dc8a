// CGAL's constrained Delaunay triangulation for discontinuity meshing, behind a header without CGAL: the
// critical lines become constrained edges (split into pieces of at most half the requested edge), a grid of
// Steiner points at that spacing fills the interior, and the constrained Delaunay triangulation of it all is
// the receiver's mesh. Exact predicates, inexact constructions: crossing critical lines are split at computed
// (rounded) intersections.
#pragma once

#include "core/refine/constrained_triangulation.h"

namespace rt::exact {

// Triangulates the domain; throws std::invalid_argument for a boundary with fewer than 3 points.
rt::PlanarTriangulation triangulateWithConstraints(const rt::PlanarDomain& domain);

// Installs triangulateWithConstraints as the core's constrained triangulator
// (rt::setConstrainedTriangulator), so that solveRefined in discontinuity mode uses it. Call once at start-up
// in programs linking rt_exact.
void registerDiscontinuityTriangulation();

}  // namespace rt::exact
