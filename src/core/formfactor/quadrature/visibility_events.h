// Where on the source the hidden part of a receiver changes form: the visibility events of one occluder.
//
// From a point x of the source, an occluder hides R ∩ S(x), S(x) the cone from x over the occluder. That
// polygon keeps the same corners and edges (each moving smoothly with x) until one of three things happens:
//  - a corner r of the receiver crosses the shadow of an occluder's edge ab (EV): x in the plane of a, b, r;
//  - the shadow of an occluder's corner v crosses an edge r1 r2 of the receiver (VE): x in the plane of v,
//  r1,
//    r2;
//  - a face of the occluder turns edge-on and its silhouette changes: x in the face's plane.
// Each is a plane, so each meets the source's plane in a line. Cut along those lines, the source falls into
// cells in each of which the hidden form factor is analytic (a fixed formula in x), so Gauss rules converge
// fast there, and whether anything or everything is hidden is the same throughout a cell. This holds for
// one convex solid or one polygon.
//
// Two whole convex solids add two kinds of event: the shadow of one's corner crosses the shadow of the
// other's edge (x in the plane of that corner and edge: cut along it too), and the crossing of two shadow
// edges slides over a receiver's edge (three edges: a quadric, which no line cut follows). Across the
// quadric the hidden part changes smoothly (a corner of it appears or goes, as across the other events) but
// a gap can open between the two shadows: the centre of a cell may see the receiver wholly hidden and its
// edge not. HiddenIntegral::overCells() therefore takes such a cell as wholly hidden only where one solid is
// proven to hide the receiver from all of it, and rates it like any other otherwise.
//
// Only the part of a line the event can happen on is kept (the shadow of edge ab falls on r from the
// central projection of ab from r onto the source's plane), and a solid's edges only where they can be on
// its silhouette from some point of the source, so a cell boundary is drawn only where it matters.
#pragma once

#include <vector>

#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/quadrature/source_panels.h"

namespace rt {

// A plane that cuts the source's plane along an event line.
struct EventPlane {
  Vec3 origin, normal;  // normal not unit
  // Where the event happens on the source's plane, when that is a segment of the line (`bounded`): cells it
  // misses are not cut along the line.
  Vec3 from = Vec3::Zero(), to = Vec3::Zero();
  bool bounded = false;
};

// Cuts `panel` along `planes` (ShadowClipper::eventPlanes()) into convex cells, appended to `cells`;
// corners within `eps` (a length) of a plane count as on it. Returns false (leaving `cells` as it found
// them) when more than `maxCells` would be made.
bool cutAlongEvents(const SourcePanel& panel, const std::vector<EventPlane>& planes, double eps, int maxCells,
                    std::vector<ConvexPolygon>& cells);

}  // namespace rt
