// The solid angle of a patch seen from a point: the patch, the unit sphere about the point (drawn at a
// radius that suits the scene), the rays to the patch's corners and the patch's central projection onto the
// sphere, whose area over the radius squared is the solid angle. Public header: no VTK.
#pragma once

#include <string>
#include <vector>

#include "core/vec.h"
#include "viz/figure_output.h"

namespace rt::viz {

struct SolidAngleConstruction {
  Vec3 point;
  Polygon patch;
  double radius = 1;           // of the sphere as drawn
  std::vector<Vec3> onSphere;  // the patch's outline projected onto the sphere (dense, closed)
  double solidAngle = 0;       // exact, sr
  double smallPatch = 0;       // A cos(theta) / r^2, sr
  double distance = 0, tiltDegrees = 0;
};

// samplesPerEdge: points per edge of the projected outline (edges become great-circle arcs).
SolidAngleConstruction solidAngleConstruction(const Vec3& point, const Polygon& patch, double solidAngle,
                                              double smallPatch, int samplesPerEdge = 48);

struct SolidAngleViewOptions {
  FigureSize size{900, 700, 96.0};
  std::string title = "Solid angle";
};

// PNG; PDF/SVG embed the rendered image.
void writeSolidAngleFigure(const SolidAngleConstruction& construction, const SolidAngleViewOptions& options,
                           const std::string& path);

}  // namespace rt::viz
