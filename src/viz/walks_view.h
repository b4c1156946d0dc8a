// Random walks drawn in the scene (core/solvers/random_walks.h): the walks a walk solver followed, one
// colour per walk, over the scene drawn faintly. A discrete walk has no point on an element (it jumps by
// F's rows), so it is drawn from element centroid to element centroid; a continuous walk (a photon) is
// drawn as the polyline of the points the ray tracer found. Each walk's source is a large dot, every landing
// a small one, and where it was absorbed a dark ball; an escaped walk simply stops. Public header: no VTK.
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/scene.h"
#include "core/solvers/random_walks.h"
#include "viz/figure_output.h"

namespace rt::viz {

// One panel: the walks of one solver, with its title.
struct WalksPanel {
  std::string title;
  std::vector<RecordedWalk> walks;
};

struct WalksViewOptions {
  FigureSize size{1200, 900, 96.0};
};

// The panels side by side. Throws std::invalid_argument without panels or for a walk whose elements are
// not in the mesh, std::runtime_error when the file cannot be written.
void writeWalksFigure(const Mesh& mesh, const Camera& camera, const std::vector<WalksPanel>& panels,
                      const WalksViewOptions& options, const std::string& path);

}  // namespace rt::viz
