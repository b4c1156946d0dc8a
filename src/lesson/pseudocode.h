// Algorithm listings in lesson text: a fenced block ```pseudocode whose first lines name it and caption it,
//
//     ```pseudocode
//     id: shooting
//     caption: Progressive refinement (Southwell with ambient)
//     for each element $i$ do                      // core/solvers/southwell.cpp: shoot()
//       $\Delta B_i \gets 0$
//     ```
//
// then one line of the algorithm per line: two spaces of indentation per level, maths in $...$, keywords
// (for, while, if, return...) set in bold, and an optional trailing "// file: function" naming the code that
// does that line, shown as a small note beside it. Listings are numbered "Algorithm <chapter>.<k>" in
// reading order, like equations, and @alg:id in the text becomes a link "Algorithm 10.1".
#pragma once

#include <map>
#include <string>
#include <vector>

#include "lesson/lesson.h"
#include "lesson/maths.h"

namespace rt::lesson {

struct PseudocodeLine {
  std::string code;    // without its indentation and note
  int indent = 0;      // levels
  std::string source;  // "core/solvers/southwell.cpp: shoot()", or empty
  int line = 0;        // file line
};

struct Pseudocode {
  std::string id, caption;
  std::vector<PseudocodeLine> lines;
  int line = 0;                    // file line of the opening fence
  std::size_t begin = 0, end = 0;  // offsets of the block, fences included, in the Markdown
};

// The listings of one Markdown text. A listing without id or caption, with a malformed id or without lines
// is an InputError at its line.
std::vector<Pseudocode> findPseudocode(const std::string& markdown, int firstLine, const std::string& file);

// The numbers of a lesson's listings by id, "<order>.<k>". An id used twice is an InputError.
using AlgorithmNumbers = std::map<std::string, std::string>;
AlgorithmNumbers numberAlgorithms(const Lesson& lesson);

// The listing as one HTML block (a figure holding a table of numbered lines), its maths as <x-equation>
// elements for the typesetter; its anchor id is "alg-<id>".
std::string pseudocodeHtml(const Pseudocode& listing, const std::string& number);

// The Markdown with @alg:id references as links and the listings as HTML. An unknown reference is an
// InputError at its line. Run it after everything that edits the text in place: it changes the line count.
std::string preparePseudocode(const std::string& markdown, int firstLine, const std::string& file,
                              const AlgorithmNumbers& numbers);

// The maths of every listing of a lesson, with its file line, for the typesetting check.
std::vector<Formula> algorithmFormulas(const Lesson& lesson);

}  // namespace rt::lesson
