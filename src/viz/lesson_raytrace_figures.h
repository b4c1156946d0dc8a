// The views of a lesson's raytrace step (ray tree, shadows, epsilon, ray cost, Whitted against radiosity),
// drawn from its RayTraceData. Internal to rt_viz: renderStepFigures (lesson_figures.h) calls it.
#pragma once

#include <string>

#include "lesson/lesson.h"
#include "lesson/step_result.h"
#include "viz/lesson_figures.h"

namespace rt::viz::detail {

// Writes `path` and returns the caption. Throws std::runtime_error when the step traced no rays.
std::string renderRayTraceView(lesson::View view, const lesson::Step& step, const lesson::StepResult& result,
                               const StepFigureSettings& settings, const std::string& path);

}  // namespace rt::viz::detail
