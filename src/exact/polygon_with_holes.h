// The result type of exact visibility: a planar polygon with holes in 3D (no CGAL types).
#pragma once

#include <vector>

#include "core/vec.h"

namespace rt::exact {

// A planar polygon with holes in 3D: outer boundary CCW seen from the front of the plane it lies in, holes
// clockwise.
struct PolygonWithHoles {
  Polygon outer;
  std::vector<Polygon> holes;
  double area() const;  // outer minus holes
};

}  // namespace rt::exact
