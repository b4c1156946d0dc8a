// Running lessons for a book: which lessons (`lesson render` and `book` take the same arguments), and every
// step run with its figures drawn and its text's placeholders filled in. `radiosity lesson render` writes
// the result as Markdown pages, `radiosity book` as an HTML site and a PDF.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "lesson/book.h"
#include "lesson/lesson_loader.h"

namespace rt::cli {

struct LessonArguments {
  std::vector<std::string> ids;
  bool all = false;
  std::string root;  // repository root holding lessons/ and scenes/; empty = the default
  lesson::LessonFolders folders() const;
  void add(CLI::App* command);
  // The lesson files to work on, in book order. Throws CLI::ValidationError unless lessons or --all are
  // given.
  std::vector<std::string> files() const;
};

struct RenderSettings {
  bool quick = false;
  int width = 900;
  int height = 700;
  std::string format = "png";  // of the figures: png, or svg (vectors where the view is 2D)
  // For HTML: equations and listings numbered, citations and references linked (lesson::prepareText).
  bool prepareText = false;
  std::string lessonWord = "lesson";  // what references to another lesson say: the book's are chapters
};

// Runs every step of the lessons, writes figures and numbers.json to <output>/<lesson>/ and the figures a
// build without an optional library could not draw to <output>/skipped.txt. Returns the lessons in book
// order. Errors are InputErrors at the step's line.
std::vector<lesson::RenderedLesson> renderLessons(const std::vector<std::string>& files,
                                                  const lesson::LessonFolders& folders,
                                                  const std::string& output, const RenderSettings& settings);

// The lesson's text problems, one "FILE:LINE: error: ..." each: a reference to an unknown equation or
// algorithm, a citation of an unknown work, a label used twice, a malformed listing and (in a build with Qt
// WebEngine, while a typeset::WebSession lives) a formula KaTeX cannot set.
std::vector<std::string> lessonTextProblems(const lesson::Lesson& lesson);

}  // namespace rt::cli
