// Exact visibility from a point: the receiver in its own plane, the shadows of the occluders projected onto
// it from the point, and the visible part whose form factor is integrated. The data come from the exact
// reference (exact/exact_reference.h, visibleRegion) converted to these plain types by the caller, so viz
// does not depend on CGAL. A 2D view: PNG, or true vectors in SVG/PDF. Public header: no VTK.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/vec.h"
#include "viz/drawing.h"
#include "viz/figure_output.h"

namespace rt::viz {

struct VisibilityRegions {
  int source = -1, receiver = -1;
  Vec3 point = Vec3::Zero();      // on the source element
  Polygon receiverOutline;        // the horizon-clipped receiver (3D, in the receiver's plane)
  std::vector<Polygon> shadows;   // occluders projected from the point into the receiver's plane
  std::vector<int> shadowOwners;  // the occluding element of each shadow
  std::vector<std::pair<Polygon, std::vector<Polygon>>> visible;  // outer boundary and holes
  double formFactor = 0;                                          // F(point -> visible part)
  double unoccludedFormFactor = 0;                                // F(point -> clipped receiver)
};

struct VisibilityViewOptions {
  FigureSize size{1000, 900, 96.0};
  std::string title;  // empty: chosen
};

// The receiver's plane is drawn with its first edge horizontal, fitted to the figure.
Drawing visibilityDrawing(const VisibilityRegions& regions, const VisibilityViewOptions& options);
void writeVisibilityFigure(const VisibilityRegions& regions, const VisibilityViewOptions& options,
                           const std::string& path);

}  // namespace rt::viz
