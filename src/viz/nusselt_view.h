// The Nusselt analog: the form factor from a differential area (point, normal) to a polygon equals the area
// of the polygon's projection onto the unit hemisphere over the point, projected again orthogonally onto the
// base disk, divided by pi. The construction is computed here (pure), drawn in 2D (the disk: true vectors) or
// 3D (hemisphere, receiver, both projections). Public header: no VTK.
#pragma once

#include <string>
#include <vector>

#include "core/scene.h"
#include "viz/drawing.h"
#include "viz/figure_output.h"

namespace rt::viz {

struct NusseltConstruction {
  Vec3 point, normal;
  Vec3 u, v;         // orthonormal axes of the base plane (u x v = normal)
  Polygon receiver;  // as given
  Polygon visible;   // the part in front of the point's tangent plane (horizon clipped)
  std::vector<Vec3>
      onHemisphere;          // the visible part's boundary projected onto the unit hemisphere (dense, closed)
  std::vector<Vec2> onDisk;  // ... then onto the base disk, in (u, v) coordinates
  double diskAreaFraction = 0;  // area(onDisk) / pi: the Nusselt estimate (converges with the sampling)
  // The outlines come from core's nusseltProject (core/formfactor/nusselt.h), the visible part from its
  // horizon clipping (core/formfactor/analytic.h).
  double exact = 0;  // Lambert's contour formula (core's pointToPolygonFormFactor)
};

// samplesPerEdge: points per polygon edge on the projected contour (great-circle arcs become curves on the
// disk).
NusseltConstruction nusseltConstruction(const Vec3& point, const Vec3& normal, const Polygon& receiver,
                                        int samplesPerEdge = 64);

struct NusseltViewOptions {
  FigureSize size{900, 900, 96.0};
  std::string title = "Nusselt analog";
};

Drawing nusseltDiskDrawing(const NusseltConstruction& construction, const NusseltViewOptions& options);
// The 2D disk: PNG, or true vectors in SVG/PDF.
void writeNusseltDiskFigure(const NusseltConstruction& construction, const NusseltViewOptions& options,
                            const std::string& path);
// The 3D construction: hemisphere, receiver, rays to its corners, its projection on the hemisphere and on the
// disk. PNG; PDF/SVG embed the rendered image.
void writeNusseltHemisphereFigure(const NusseltConstruction& construction, const NusseltViewOptions& options,
                                  const std::string& path);

}  // namespace rt::viz
