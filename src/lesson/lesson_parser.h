// Parsing the lesson format (docs/lesson-format.md): a front-matter header between `---` lines, then one `##
// Title` section per step holding a fenced ```step block of `key: value` parameters and the step's Markdown
// text. Everything that can be checked without reading other files is checked here; errors are rt::InputError
// naming the file and line.
#pragma once

#include <string>

#include "lesson/lesson.h"

namespace rt::lesson {

// `id` is the lesson's id (the file name without extension); `file` is used in messages.
Lesson parseLesson(const std::string& text, const std::string& id, const std::string& file);

// The keys a step block accepts (reflectance overrides are written `reflectance.<surface>`).
const std::vector<std::string>& stepKeys();
// Names of the form-factor methods and solvers a lesson may name (the registries may hold more at run time).
const std::vector<std::string>& knownMethods();
const std::vector<std::string>& knownSolvers();

}  // namespace rt::lesson
