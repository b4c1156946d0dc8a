// Occluder edges that run close to the source's plane without touching it: near-singularities of the
// hidden form factor just beyond the cells.
//
// An occluder edge at a small height h over the source's plane (a light hung 1 mm under the ceiling, seen
// from the ceiling beside it) hides from a point x at a distance d from the edge's line a part of the
// receiver that grows like h / d: the hidden form factor has a near-singularity at the edge, a distance h
// from the source's plane. The visibility events cut the source where the hidden part changes form, not
// there, so a cell can reach to within h of the edge. Over a cell, a Gauss rule converges at the rate set by
// the nearest complex singularity (source_panels.h): when the cell is wider than its distance from the edge,
// its 2 x 2 rule and its centre both see the small values far from the edge and agree, while most of the
// integral lies in a strip beside the edge that neither sees.
//
// Such a cell is therefore rated by a probe too: the hidden form factor at the cell's point nearest the edge
// against the cell's mean. Where that says the cell's value is in doubt, it is cut into strips parallel to
// the edge, each no wider than its distance from the edge (widths doubling away from it), in which the rules
// hold again. An edge counts only where what it can hide near the plane matters at the tolerance: its
// length times h times the log of the source's size over h, the integral of h / d over the strip.
#pragma once

#include <vector>

#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/quadrature/source_panels.h"

namespace rt {

class NearEdges {
 public:
  // The edges of `occluders` (the clipper's, clipped to the front of both planes) that lie over the source's
  // plane by more than the clipper's margin and less than `reach` (the cells' size), and whose integral of
  // h / d can exceed `tolerance` (absolute, in units of the hidden integral: form factor times area).
  void find(const ShadowClipper& clipper, const std::vector<int>& occluders, double reach, double tolerance);
  bool empty() const { return edges_.empty(); }

  // An edge other than `except` that `cell` is wider than its distance from (across the edge's line), or -1.
  int tooWide(const SourcePanel& cell, int except = -1) const;
  // The cell's corner or edge midpoint nearest the edge's line: where the hidden form factor peaks.
  Vec3 nearestPoint(const SourcePanel& cell, int edge) const;
  // `cell` cut into strips parallel to `edge`, each no wider than its distance from the edge, appended to
  // `out` as panels.
  void strips(const SourcePanel& cell, int edge, std::vector<SourcePanel>& out) const;

 private:
  struct Edge {
    Vec3 a;       // its first end projected onto the source's plane
    Vec3 along;   // unit, along the projected edge
    Vec3 across;  // unit, in the plane, across it
    double length = 0, height = 0;
  };
  // The cell's extent in the edge's coordinates: along [s0, s1], across [t0, t1].
  struct Extent {
    double s0, s1, t0, t1;
  };
  Extent extentOf(const SourcePanel& cell, const Edge& e) const;
  // The distance from the cell's extent to the edge, without its part across the edge's line.
  static double offAcross(const Extent& x, const Edge& e);

  std::vector<Edge> edges_;
};

}  // namespace rt
