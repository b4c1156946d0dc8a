// One pixel's ray tree (core/raytrace/ray_tree.h) in its scene: the primary and mirror rays, the shadow rays
// that reach a light and those that a blocker stops, over the scene drawn faintly. The segments and their
// colours are one mapping, which the figure and the app's 3D view both draw. Public header: no VTK.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/raytrace/ray_tree.h"
#include "core/scene.h"
#include "viz/figure_output.h"

namespace rt::viz {

struct RaySegments {
  std::string label;               // "primary", "reflection", "shadow: clear", "shadow: blocked"
  std::array<double, 3> colour{};  // linear RGB in [0, 1]
  double width = 2;                // pixels at 96 dpi
  std::vector<Vec3> points;        // two per segment
};

// The tree's rays by kind, each kind that has rays once (blocked shadow rays end at their blocker).
std::vector<RaySegments> rayTreeSegments(const RayTree& tree);

// A camera that sees the whole room and the eye the primary ray leaves from: beside and above the eye,
// looking at the middle of the scene.
Camera rayTreeCamera(const Mesh& mesh, const Camera& eye);

struct RayTreeViewOptions {
  FigureSize size{1200, 900, 96.0};
  std::string caption;
};

// PNG; PDF/SVG embed the rendered image.
void writeRayTreeFigure(const Mesh& mesh, const Camera& camera, const RayTree& tree,
                        const RayTreeViewOptions& options, const std::string& path);

}  // namespace rt::viz
