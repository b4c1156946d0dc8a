// Draws the figure a FigureRequest asks for, computing what the view needs (form factors, a solve, a refined
// mesh) through the core pipeline. `radiosity figure` is options plus this call; each view name means one
// thing here and in the lessons (lesson_figures.h draws a step's views with the same view functions).
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/scene.h"
#include "viz/figure_request.h"

namespace rt::viz {

// Writes request.output. Throws std::invalid_argument for a request that does not fit the scene (an element
// out of range, a part the view does not have), std::runtime_error when drawing fails.
void drawFigure(const Scene& scene, const MeshOptions& mesh, const FigureRequest& request);
// runtime-error from a timing table (request.input), without a scene.
void drawTimingTableFigure(const FigureRequest& request);

}  // namespace rt::viz
