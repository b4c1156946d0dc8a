// The numbers behind a step as JSON: element count, per-channel sums of B, the form factors' row sums and
// total, each solver run's iterations and residual, and every named value except run times. `radiosity lesson
// render` writes them beside each lesson's figures (numbers.json); a test checks that the app computes the
// very same numbers for every step.
#pragma once

#include <string>

#include "lesson/step_result.h"

namespace rt::lesson {

// One JSON object, keys sorted, numbers with 17 significant digits (equal text means equal doubles). Run
// times are left out: they differ between runs.
std::string stepNumbersJson(const StepResult& result);

}  // namespace rt::lesson
