// The views of a lesson's pathtrace step (traced, difference, noise, two-pass), drawn from its
// TracedPictures. Internal to rt_viz: renderStepFigures (lesson_figures.h) calls it.
#pragma once

#include <string>

#include "lesson/lesson.h"
#include "lesson/step_result.h"
#include "viz/image_panels.h"
#include "viz/lesson_figures.h"

namespace rt::viz::detail {

// The options of a step's pictures: its figure size, its display keys (exposure, tone map, gamma), a title.
ImagePanelsOptions stepPictureOptions(const lesson::Step& step, const StepFigureSettings& settings,
                                      const std::string& title);

// Writes `path` and returns the caption. Throws std::runtime_error when the step computed no pictures.
std::string renderTracedView(lesson::View view, const lesson::Step& step, const lesson::StepResult& result,
                             const StepFigureSettings& settings, const std::string& path);

}  // namespace rt::viz::detail
