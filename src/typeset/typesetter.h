// Lesson maths through KaTeX: checking every formula of a lesson (errors at their file lines) and setting the
// maths of a written HTML page in place, so that the page needs no script to show it.
#pragma once

#include <QString>
#include <string>
#include <vector>

#include "lesson/maths.h"

namespace rt::typeset {

struct MathsReport {
  int formulas = 0;
  std::vector<std::string> errors;  // KaTeX's messages
};

// Typesets each formula with KaTeX (as strict as the pages: an error is an error) and returns one message per
// formula that fails, "FILE:LINE: error: formula does not typeset: ...", in the order given. Needs a
// WebSession (or the app's QApplication).
std::vector<std::string> checkFormulas(const std::vector<lesson::Formula>& formulas, const std::string& file);

// Loads the HTML file, sets its <x-equation> elements with KaTeX and writes it back without any script.
// Throws std::runtime_error when the page cannot be loaded or written.
MathsReport typesetHtmlFile(const QString& path);

}  // namespace rt::typeset
