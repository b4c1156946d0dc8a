// The figures of a lesson step now live in the viz library (viz/lesson_figures.h); these are the names under
// which the app's code first used them.
#pragma once

#include "viz/lesson_figures.h"

namespace rt::cli {

using FigureSettings = viz::StepFigureSettings;
using viz::renderStepFigures;

}  // namespace rt::cli
