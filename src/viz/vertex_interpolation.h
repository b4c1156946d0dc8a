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
// Smooth regions: elements that may be averaged together get the same label (labels are 0..k-1).
std::vector<int> smoothRegions(const Mesh& mesh);

}  // namespace rt::viz
