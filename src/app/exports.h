// What the app writes: the current view as PNG/SVG/PDF, matrices and vectors as CSV/MTX/NPY/TeX, and every
// figure of a lesson at once. The writers are the ones the command line uses (viz figure functions,
// rt::writeMatrix), so a file exported from the app is the file `radiosity` writes for the same inputs.
#pragma once

#include <functional>
#include <string>

#include "app/pipeline.h"
#include "viz/scene_view.h"

namespace rt::app {

class LessonLibrary;

// The 3D view of `result` from `camera`, as the figure exporter renders it (format from the extension).
void exportSceneFigure(const Mesh& mesh, const Camera& camera, const viz::SceneViewData& data,
                       const viz::SceneViewOptions& options, const std::string& path);

// The form-factor matrix (n x n), or K = I - diag(rho_channel) F when `which` is "K", or B (n x 3) when "B".
void exportMatrix(const PipelineResult& result, const std::string& which, const std::string& path);

// Runs every step of the lesson and writes its figures, as `radiosity lesson render` draws them (one file per
// view, named by the step's figure) into `folder`. Returns the number of files written; `onStep` is told of
// each step (it may throw Cancelled to stop).
int exportLessonFigures(LessonLibrary& library, int lessonIndex, const std::string& folder, int width,
                        int height, Progress& progress,
                        const std::function<void(int step, int steps)>& onStep = {});

}  // namespace rt::app
