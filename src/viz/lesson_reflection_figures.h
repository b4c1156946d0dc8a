// The views of a lesson's reflection step (the BRDF's lobe in 3D, Phong's cos^q sweep, the directional
// albedo, Phong local illumination beside radiosity), drawn from its ReflectionData. Internal to rt_viz:
// renderStepFigures (lesson_figures.h) calls it.
#pragma once

#include <string>

#include "lesson/lesson.h"
#include "lesson/step_result.h"
#include "viz/lesson_figures.h"

namespace rt::viz::detail {

// Writes `path` and returns the caption. Throws std::runtime_error when the step is not a reflection step or
// (phong-local) lit no scene.
std::string renderReflectionView(lesson::View view, const lesson::Step& step,
                                 const lesson::StepResult& result, const StepFigureSettings& settings,
                                 const std::string& path);

}  // namespace rt::viz::detail
