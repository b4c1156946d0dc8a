// The views of a lesson's radiometry step (solid angle, cosine law, inverse square), drawn from its
// RadiometryData. Internal to rt_viz: renderStepFigures (lesson_figures.h) calls it.
#pragma once

#include <string>

#include "lesson/lesson.h"
#include "lesson/step_result.h"
#include "viz/lesson_figures.h"

namespace rt::viz::detail {

// Writes `path` and returns the caption. Throws std::runtime_error when the step is not a radiometry step.
std::string renderRadiometryView(lesson::View view, const lesson::StepResult& result,
                                 const StepFigureSettings& settings, const std::string& path);

}  // namespace rt::viz::detail
