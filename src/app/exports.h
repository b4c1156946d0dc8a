// What the app writes: the current view as PNG/SVG/PDF, matrices and vectors as CSV/MTX/NPY/TeX (every figure
// of a lesson at once: figure_export.h). The writers are the ones the command line uses (viz figure
// functions, rt::writeMatrix), so a file exported from the app is the file `radiosity` writes for the same
// inputs.
#pragma once

#include <string>

#include "app/pipeline.h"
#include "viz/scene_view.h"

namespace rt::app {

// The 3D view of `result` from `camera`, as the figure exporter renders it (format from the extension).
void exportSceneFigure(const Mesh& mesh, const Camera& camera, const viz::SceneViewData& data,
                       const viz::SceneViewOptions& options, const std::string& path);

// The form-factor matrix (n x n), or K = I - diag(rho_channel) F when `which` is "K", or B (n x 3) when "B".
void exportMatrix(const PipelineResult& result, const std::string& which, const std::string& path);

}  // namespace rt::app
