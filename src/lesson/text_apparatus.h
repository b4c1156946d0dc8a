// A lesson's text made ready for a page: equations numbered, algorithm listings set and numbered, citations
// linked, references (@eq:, @alg:, @lesson:) resolved. The app's text pane, the HTML book and the PDF all
// call prepareText, so they number and cite alike.
#pragma once

#include <string>
#include <vector>

#include "lesson/bibliography.h"
#include "lesson/glossary.h"
#include "lesson/lesson.h"
#include "lesson/lesson_references.h"
#include "lesson/maths.h"
#include "lesson/pseudocode.h"

namespace rt::lesson {

struct TextApparatus {
  EquationNumbers equations;
  AlgorithmNumbers algorithms;
  Bibliography bibliography;            // the references.json beside the lesson file
  LessonNumbers lessons;                // the chapter numbers of the lessons beside it
  std::vector<GlossaryEntry> glossary;  // the glossary.json beside the lesson file
  std::string lessonWord = "lesson";  // what @lesson: references say: "lesson 6", or in the book "chapter 6"
};

// Numbers the lesson's equations and listings and reads its bibliography and glossary. InputError on a label
// used twice or a malformed bibliography or glossary.
TextApparatus lessonApparatus(const Lesson& lesson);

// One text of the lesson (its introduction or a step's text, placeholders filled in) ready for Markdown to
// HTML. Errors are InputErrors at the line in `file`.
std::string prepareText(const std::string& markdown, int firstLine, const std::string& file,
                        const TextApparatus& apparatus);

// "Further reading" for a page: the works the keys name, sorted by author, as an HTML list (empty when
// there are none) under a heading of level `level` (0: no heading).
std::string furtherReading(const std::vector<std::string>& keys, const Bibliography& bibliography, int level);

// The problems of a lesson's text that need no typesetter, one "FILE:LINE: error: ..." each: unknown
// equations, algorithms, lessons or cited works, labels used twice, malformed listings or citations.
std::vector<std::string> textProblems(const Lesson& lesson);

// The style of listings, citations and reference lists, shared by the book's pages and the app.
std::string apparatusStyleSheet();

}  // namespace rt::lesson
