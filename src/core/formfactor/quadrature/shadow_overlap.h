// Whether two convex solids can hide the same part of a receiver from a source: whether one segment from
// the source to the receiver can pass through both.
//
// A pair that two blocks shade has events where the shadows' edges cross each other on the receiver (three
// edges in line, a quadric), which no cell cut along planes captures (visibility_events.h), so it is left to
// the adaptive rules with their guards, at several times the cost of cells. But where the two shadows never
// overlap, the hidden part is the sum of what each block hides alone, and each of those is cut into cells.
//
// The proof: a segment from x on the source S to y on the receiver R that passes through a point p of solid
// A and then a point q of solid B has q on the segment from p to y, inside the convex hull of A and R, and p
// on the segment from x to q, inside the convex hull of S and B. So B outside hull(A, R), or A outside
// hull(S, B), rules that order out; the same with A and B swapped rules out the other. Each is a separation
// of two convex hulls of points, proven by a plane between them: parallel to a face of one or to an edge of
// each (the separating axis theorem), all of which are tried.
#pragma once

#include <utility>
#include <vector>

#include "core/formfactor/quadrature/solid_silhouette.h"
#include "core/vec.h"

namespace rt {

// True when the solid `other` lies outside the convex hull of the solid `near` and the convex polygon
// `polygon` (`count` corners), by more than `eps` (a length) from a separating plane.
bool solidOutsideHullOfSolidAndPolygon(const SolidShape& other, const SolidShape& near, const Vec3* polygon,
                                       int count, double eps);

// The proof from its hull tests: `outside(e, near, other)` tells whether solid `other` lies outside the
// convex hull of solid `near` and element e (solids 0 and 1 the two; elements 0 the source, 1 the receiver).
// Each order along the segment needs one of its two tests.
template <class Outside>
bool shadowsApartBy(Outside&& outside) {
  return (outside(1, 0, 1) || outside(0, 1, 0)) && (outside(1, 1, 0) || outside(0, 0, 1));
}

// True when a plane keeps the convex hulls of the points `p` and of the points `q` more than `eps` from it on
// either side. `pEdges` and `qEdges` (pairs of indices) hold every edge of each hull; `qNormals` the face
// normals of q's hull (may be empty). Faces of p's hull are taken as planes through each of its edges and
// each of its points.
bool hullsSeparated(const Vec3* p, int np, const std::vector<std::pair<int, int>>& pEdges, const Vec3* q,
                    int nq, const std::vector<std::pair<int, int>>& qEdges, const std::vector<Vec3>& qNormals,
                    double eps);

}  // namespace rt
