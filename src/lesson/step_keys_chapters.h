// The step keys of the chapters on light, reflection and ray tracing (the radiometry, reflection and raytrace
// stages): rows of the one step-key table (step_keys.cpp), kept apart because each chapter adds several.
#pragma once

#include <vector>

#include "lesson/step_keys.h"

namespace rt::lesson {

void addChapterKeys(std::vector<StepKey>& t);

}  // namespace rt::lesson
