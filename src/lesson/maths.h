// Mathematics in lesson text is LaTeX: $...$ inline, $$...$$ displayed. Every displayed equation is numbered
// <lesson order>.<k> in reading order (introduction, then the steps); one followed by {#eq:name} can be
// referred to in the text as @eq:name, which becomes a link "(3.2)". Maths is found by the same Markdown
// parser that writes the HTML (md4c), so a '$' in a code span or block is never taken for maths. The
// typesetting itself (KaTeX) is done by the programs (src/typeset); this layer finds, numbers and prepares
// the formulas and knows the line each came from, so that a formula that fails to typeset is reported at its
// line.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "lesson/lesson.h"

namespace rt::lesson {

struct Formula {
  std::string tex;  // as written, between the dollars
  bool display = false;
  int line = 0;           // file line of its first character
  std::string label;      // displayed equations followed by {#eq:label}: the label
  std::size_t begin = 0;  // offsets of the TeX in the Markdown text
  std::size_t end = 0;
};

// The formulas of one Markdown text, in order. `firstLine` is the file line of the text's first line.
std::vector<Formula> findFormulas(const std::string& markdown, int firstLine);

// The numbers of a lesson's displayed equations: by the file line of the equation and by label.
struct EquationNumbers {
  std::map<int, std::string> byLine;
  std::map<std::string, std::string> byLabel;
};

// Numbers every displayed equation of the lesson. A label used twice is an InputError at the second one.
EquationNumbers numberEquations(const Lesson& lesson);

// The Markdown with its maths ready for the HTML page: displayed equations get \tag{number} and an anchor
// id "eq-<label>", the {#eq:label} marks are removed, and @eq:label references become links "(number)". An
// unknown reference is an InputError naming `file` and its line. Placeholders must be filled in already (the
// text keeps its lines, so `firstLine` is the same as for the text as written).
std::string prepareMaths(const std::string& markdown, int firstLine, const std::string& file,
                         const EquationNumbers& numbers);

// A reference "@<kind>:label" in the text outside code and maths ("@eq:radiosity", "@alg:shooting"): its
// offsets in the Markdown (a sentence's closing punctuation is not part of the label), label and file line.
struct LabelReference {
  std::size_t begin = 0, end = 0;
  std::string label;
  int line = 0;
};
std::vector<LabelReference> findReferences(const std::string& markdown, int firstLine,
                                           const std::string& kind);

// The pieces [begin, end) of the Markdown that are normal text: not code, not maths, not HTML.
std::vector<std::pair<std::size_t, std::size_t>> plainTextPieces(const std::string& markdown);
// The same pieces without those inside a link's text (where no second link may go).
std::vector<std::pair<std::size_t, std::size_t>> unlinkedTextPieces(const std::string& markdown);

// Every formula of a lesson, with its file line and placeholders replaced by sample numbers: what the
// typesetter checks when the lesson or the book is built.
std::vector<Formula> lessonFormulas(const Lesson& lesson);

// CSS for KaTeX's displayed equations, the same in the app's pane and the book: a numbered equation is
// centred in the width its number leaves, the number flush right, and a line too narrow for both puts the
// number under the equation (as LaTeX does) instead of over its last terms.
std::string equationStyleSheet();

}  // namespace rt::lesson
