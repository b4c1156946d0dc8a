// The error chart of a lesson's elements step: each basis's error against the number of elements, over the
// scene and over each highlighted surface, with the fitted orders. Internal to rt_viz: renderStepFigures
// (lesson_figures.h) calls it.
#pragma once

#include <string>

#include "lesson/step_result.h"
#include "viz/lesson_figures.h"

namespace rt::viz::detail {

// Writes `path` and returns the caption. Throws std::runtime_error when the step measured no bases.
std::string renderBasisErrorView(const lesson::StepResult& result, const StepFigureSettings& settings,
                                 const std::string& path);

}  // namespace rt::viz::detail
