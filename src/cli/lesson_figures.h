// The figures of a lesson step: one file per view, drawn by the viz layer from the step's result.
#pragma once

#include <string>
#include <vector>

#include "lesson/book.h"
#include "lesson/lesson.h"
#include "lesson/step_result.h"

namespace rt::cli {

struct FigureSettings {
  int width = 900;
  int height = 700;
};

// Whether this build can draw figures (it was built with the viz library).
bool canRenderFigures();

// Writes the step's figures into `dir` (file names from Step::figureFiles()) and returns them with captions
// (paths relative to dir's parent, for the book). Throws std::runtime_error when drawing fails.
std::vector<lesson::RenderedFigure> renderStepFigures(const lesson::Lesson& lesson, const lesson::Step& step,
                                                      const lesson::StepResult& result,
                                                      const std::string& dir, const FigureSettings& settings);

}  // namespace rt::cli
