// The meaning of a step's ```step block: each `key: value` line applied to the step (the keys that describe
// the step itself here, the parameters through the step-key table), and the checks across keys once the
// block is complete. The lesson parser (lesson_parser.h) finds the blocks; errors name the file and line.
#pragma once

#include <string>

#include "core/input_error.h"
#include "lesson/lesson.h"

namespace rt::lesson {

// Applies one line of the block; `where` is its file and line.
void applyStepField(Step& step, const std::string& key, const std::string& value,
                    const SourceLocation& where);

// The checks that need the whole block (a stage's required keys, views the stage can show, a figure name for
// the views...); also sets what follows from several keys (the caption's view).
void finishStep(Step& step, const std::string& file);

}  // namespace rt::lesson
