// Citations in lesson text: [@key], [@key, p. 12] (a locator after a comma) and [@a; @b], outside code and
// maths, on one line. Each becomes author-year links, "(Goral et al. 1984; Cohen and Greenberg 1985)", to the
// entry's anchor "ref-<key>" (the chapter's further reading, the app's list under the step), with the full
// entry as the link's title, which the app and the HTML pages show on hover.
#pragma once

#include <string>
#include <vector>

#include "lesson/bibliography.h"
#include "lesson/lesson.h"

namespace rt::lesson {

struct CitedWork {
  std::string key;
  std::string locator;  // "p. 12", or empty
};

struct Citation {
  std::vector<CitedWork> works;
  int line = 0;
  std::size_t begin = 0, end = 0;  // the brackets' offsets in the Markdown
};

// The citations of one Markdown text. A malformed one ("[@]", "[@a; b]", not closed on its line) is an
// InputError naming `file` and its line.
std::vector<Citation> findCitations(const std::string& markdown, int firstLine, const std::string& file);

// The keys a text or a whole lesson (introduction, then steps) cites, each once, in order of first citation.
std::vector<std::string> citedKeys(const std::string& markdown, int firstLine, const std::string& file);
std::vector<std::string> citedKeys(const Lesson& lesson);

// The Markdown with its citations as links. A key the bibliography lacks is an InputError at its line.
std::string prepareCitations(const std::string& markdown, int firstLine, const std::string& file,
                             const Bibliography& bibliography);

}  // namespace rt::lesson
