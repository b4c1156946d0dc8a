// The views of a lesson's scaling step (memory, cost, links, noise, clusters), drawn from its ScalingData,
// and of its sampling step (error against rays per variance reduction). Internal to rt_viz:
// renderStepFigures (lesson_figures.h) calls them.
#pragma once

#include <string>

#include "lesson/lesson.h"
#include "lesson/step_result.h"
#include "viz/lesson_figures.h"

namespace rt::viz::detail {

// Writes `path` and returns the caption. Throws std::runtime_error when the step measured no scaling.
std::string renderScalingView(lesson::View view, const lesson::Step& step, const lesson::StepResult& result,
                              const StepFigureSettings& settings, const std::string& path);
// The sampling-error chart. Throws std::runtime_error when the step measured no sampling.
std::string renderSamplingView(const lesson::StepResult& result, const StepFigureSettings& settings,
                               const std::string& path);

}  // namespace rt::viz::detail
