// The exact geometric kernel of the reference, behind a plain interface: the only declarations whose
// definitions use CGAL (exact_kernel_cgal.cpp: projection and 2D Booleans; segment_visibility_cgal.cpp: AABB
// tree). Everything else in src/exact is plain C++ so that editing it never recompiles CGAL.
#pragma once

#include <vector>

#include "core/vec.h"
#include "exact/polygon_with_holes.h"

namespace rt::exact::detail {

// Number type for the clipping and central projection (the "kernel" in the CGAL sense).
enum class Arithmetic {
  Exact,     // CGAL::Exact_predicates_exact_constructions_kernel (lazy exact rationals)
  Floating,  // CGAL::Exact_predicates_inexact_constructions_kernel (doubles, exact predicates only)
};

// The geometric core of visibility from a point: the receiver clipped to the half-space in front of the
// source plane at x, and every occluder clipped to the pyramid from x over that receiver (between x and the
// receiver's plane) and projected centrally from x into the receiver's plane. Polygons with fewer than 3
// distinct vertices or zero area (occluders seen edge-on, occluders through x) are dropped. Results are CCW
// seen from the receiver's front.
struct ProjectionResult {
  bool receiverFacesPoint =
      false;  // x strictly in front of the receiver's plane and some receiver area in front of x
  Polygon clippedReceiver;
  std::vector<Polygon> projections;
  std::vector<int> projectionOwners;  // index into the occluder list of each projection
};

ProjectionResult projectOccluders(const Vec3& x, const Vec3& sourceNormal, const Polygon& receiver,
                                  const Vec3& receiverNormal, const std::vector<Polygon>& occluders,
                                  Arithmetic arithmetic);

// Visible part of the receiver from x: clipped receiver minus the union of the projections, by exact 2D
// Boolean set operations (exact constructions kernel) in the receiver's plane coordinates; converted to
// double at the end and lifted back onto the receiver's plane. Outer boundaries CCW seen from the receiver's
// front, holes clockwise.
struct ExactVisibility {
  ProjectionResult projection;
  std::vector<PolygonWithHoles> visible;
};

ExactVisibility exactVisibility(const Vec3& x, const Vec3& sourceNormal, const Polygon& receiver,
                                const Vec3& receiverNormal, const std::vector<Polygon>& occluders);

}  // namespace rt::exact::detail
