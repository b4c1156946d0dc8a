// Each lesson's exercises test that lesson: an exercise step may name only a homework topic whose row in the
// topic table (homework/topic_table.cpp, the one place that says which topics fit a lesson) lists the
// lesson's id. `radiosity lesson check` reports the others at their file and line.
#pragma once

#include <string>
#include <vector>

#include "lesson/lesson.h"

namespace rt::lesson {

// "file:line: ..." for every exercise step whose topic does not list the lesson.
std::vector<std::string> exerciseTopicProblems(const Lesson& lesson);

}  // namespace rt::lesson
