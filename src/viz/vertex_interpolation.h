// Smooth display of piecewise-constant radiosity: per-corner values interpolated from the elements around
// each vertex, in the classic scheme of Cohen and Wallace (Radiosity and Realistic Image Synthesis, 1993, ch.
// 9):
// - only elements of the same smooth region (coplanar, same material, connected) are averaged, so that
// creases and
//   material boundaries stay sharp;
// - an interior vertex takes the average of the elements around it;
// - a vertex on the region's boundary is extrapolated, 2 B_e - (mean of e's interior corners), so that the
// element's
//   average stays close to B_e instead of being pulled towards its neighbours;
// - a T-vertex (a corner of small elements lying on the edge of a larger one) takes the value interpolated
// along
//   that edge, so that the shading is continuous across it (no crack in the colour).
// Pure functions, no VTK.
#pragma once

#include <vector>

#include "core/mesh.h"

namespace rt::viz {

// One value per element corner: corner k of element e is row firstCorner[e] + k of values.
struct CornerField {
  std::vector<int> firstCorner;  // size n + 1
  RgbField values;
  Rgb at(int element, int corner) const {
    return values.row(firstCorner[element] + corner).transpose().array();
  }
};

// Each corner carries its element's value.
CornerField flatCornerValues(const Mesh& mesh, const RgbField& perElement);
// The smooth scheme above; negative extrapolations are clamped to zero.
CornerField smoothCornerValues(const Mesh& mesh, const RgbField& perElement);

// The smooth scheme split into what depends on the mesh alone (regions, which vertices are interior,
// T-vertices, the least-squares weights of each boundary extrapolation), found once, and its application to
// a field, a few passes over the corners: the app replays iterations and changes tone maps on a million
// elements without finding the mesh's structure again. apply() gives smoothCornerValues' values.
class SmoothInterpolation {
 public:
  explicit SmoothInterpolation(const Mesh& mesh);
  CornerField apply(const RgbField& perElement) const;
  std::size_t elements() const { return firstCorner_.empty() ? 0 : firstCorner_.size() - 1; }

 private:
  struct Term {  // B_e + sum_k weight_k (B_neighbour_k - B_e), clamped at zero
    int element = 0;
    int firstWeight = 0, lastWeight = 0;  // into neighbours_ / weights_
  };
  struct TVertex {
    int slot = 0, a = 0, b = 0;  // slots of the vertex and of the long edge's ends
    double t = 0;
  };
  std::vector<int> firstCorner_;  // as CornerField's
  std::vector<int> cornerSlot_;   // corner -> (region, vertex) slot
  // Per slot: the elements averaged (interior) or extrapolated from (boundary), CSR.
  std::vector<int> firstTerm_;
  std::vector<Term> terms_;
  std::vector<char> extrapolated_;  // per slot: boundary (terms extrapolate) or interior (plain average)
  std::vector<int> neighbours_;
  std::vector<double> weights_;
  std::vector<TVertex> tVertices_;  // in (region, vertex) order, applied twice
};
// Smooth regions: elements that may be averaged together get the same label (labels are 0..k-1).
std::vector<int> smoothRegions(const Mesh& mesh);

}  // namespace rt::viz
