// Where the integrand of an occluded entry, F(x) = F(dA at x -> visible part of the receiver), may have a
// kink on the source element: the lines of the source plane on which the visibility structure changes. Within
// a cell that no such line crosses, F(x) is a smooth (analytic) function and Gauss rules converge fast;
// across them its derivative jumps, which costs isotropic refinement ~1/h cells per line. Splitting the
// source along them before adapting is what makes the occluded entries affordable to 1e-6.
//
// The events found are the vertex-edge ones (EV, VE: a vertex and an edge, of the receiver or of the
// occluders, line up as seen from x), which are straight lines in the source plane. Edges that can never be
// on the boundary of the occluders' shadow (an edge shared by two coplanar occluders: the inner mesh lines of
// a block face) and vertices in the middle of a straight boundary are left out, and so is an edge two
// occluders share at an angle wherever the event's plane passes between them (a convex solid's vertex and
// edge then line up only in its face planes). Edge-edge-edge events
// (conics) are not split along; the adaptive refinement still finds them, only more slowly.
#pragma once

#include <vector>

#include "core/vec.h"
#include "exact/shaft.h"

namespace rt::exact {

// A piece of an event line inside the integration domain (both ends in the source plane).
struct EventSegment {
  Vec3 a, b;
};

std::vector<EventSegment> visibilityEvents(const PairGeometry& pair);

// Splits the convex domain (in the plane with unit normal `normal`) by the full lines of the segments that
// cross it, until no segment crosses the interior of a cell by more than `margin`, or `maxCells` is reached.
// The cells are convex and tile the domain.
std::vector<Polygon> splitAlongEvents(const Polygon& domain, const Vec3& normal,
                                      const std::vector<EventSegment>& events, double margin,
                                      std::size_t maxCells = 2048);

}  // namespace rt::exact
