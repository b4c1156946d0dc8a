// Writing an assignment to disk: per student a folder with the handout (Markdown with $...$ maths and
// SVG figures; LaTeX source with the same figures as LaTeX pictures), the data files (scene JSON/OBJ;
// matrices as CSV, Matrix Market and NPY) and a blank answer file; for the instructor the key (key.json for
// the grader, key.md and key.tex with every worked solution).
#pragma once

#include <string>
#include <vector>

#include "homework/answer_key.h"

namespace rt::homework {

// The handout of one student as Markdown (figures and data referenced relative to the student's folder).
std::string handoutMarkdown(const StudentExercises& student, std::uint64_t seed);

// An exercise as a book prints it: the statement and the questions, answers in the appendix.
std::string exerciseBookText(const Exercise& exercise);
struct AppendixEntry {
  std::string where;  // e.g. "3.6 Exercise: Two rectangles"
  Exercise exercise;
};
// The book's appendix: every exercise's answers and worked solution, under its own lesson-like page id.
inline constexpr const char* kAnswersAppendixId = "exercise-answers";
std::string answersAppendix(const std::vector<AppendixEntry>& entries);

// Writes DIR/<student>/{handout.md, handout.tex, answers.txt, figures/, data/} for every student and
// DIR/key.{json,md,tex}. Returns the Markdown files written (handouts, then the key), which the programs
// typeset to PDF. Throws InputError naming a path that cannot be written.
std::vector<std::string> writeAssignment(const Assignment& assignment, const std::string& directory);

}  // namespace rt::homework
