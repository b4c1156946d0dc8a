// What the app writes: the current view as PNG/SVG/PDF, matrices and vectors as CSV/MTX/NPY/TeX (every figure
// of a lesson at once: figure_export.h). The writers are the ones the command line uses (viz figure
// functions, rt::writeMatrix), so a file exported from the app is the file `radiosity` writes for the same
// inputs.
#pragma once

#include <string>
#include <vector>

#include "app/pipeline.h"
#include "lesson/lesson.h"
#include "lesson/step_result.h"
#include "viz/scene_view.h"

namespace rt::app {

// The 3D view of `result` from `camera`, as the figure exporter renders it (format from the extension).
void exportSceneFigure(const Mesh& mesh, const Camera& camera, const viz::SceneViewData& data,
                       const viz::SceneViewOptions& options, const std::string& path);

// The form-factor matrix (n x n), or K = I - diag(rho_channel) F when `which` is "K", or B (n x 3) when "B".
// A .tex file is a whole document that compiles as it is (texLatexDocument).
void exportMatrix(const PipelineResult& result, const std::string& which, const std::string& path);

// The bmatrix that rt::writeMatrix writes, made a document that compiles at any size: amsmath's bmatrix
// stops at 10 columns unless MaxMatrixCols says more, and "-4.28698e-06" is not a number to TeX, so small and
// large numbers become "-4.28698 \times 10^{-6}". The matrix stays between its own begin/end lines, for a
// reader who \input's it elsewhere.
std::string latexDocument(const std::string& bmatrix, long long columns);

// The step's figures other than the live 3D view, drawn by the book's code (viz::renderStepFigures) into
// `folder` as `format` files ("png", "svg", "pdf"; the 2D figures are vectors in svg and pdf), named `name`
// (one figure: name.format; several: name-view.format) or, when `name` is empty, by the step's `figure:`.
// Returns the paths written.
std::vector<std::string> exportStepFigures(const lesson::Lesson& lesson, const lesson::Step& step,
                                           const lesson::StepResult& result, const std::string& folder,
                                           const std::string& format, const std::string& name = {});

}  // namespace rt::app
