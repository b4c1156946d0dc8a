// The cluster hierarchy of hierarchical radiosity with clustering, cut at one depth: each node's box drawn as
// a wireframe over the scene (the solution, faint), so that a reader sees which elements one link between
// two clusters stands for. Public header: no VTK.
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/scene.h"
#include "lesson/scaling_data.h"
#include "viz/figure_output.h"

namespace rt::viz {

struct ClusterViewOptions {
  FigureSize size{1200, 900, 96.0};
  std::string caption;
};

// B: the scene's radiosity (n x 3) shown under the boxes; empty shows the reflectance. PNG; PDF/SVG embed
// the rendered image. Throws std::invalid_argument when there are no boxes.
void writeClusterFigure(const Mesh& mesh, const RgbField& B, const Camera& camera,
                        const std::vector<lesson::ClusterBox>& boxes, const ClusterViewOptions& options,
                        const std::string& path);

}  // namespace rt::viz
