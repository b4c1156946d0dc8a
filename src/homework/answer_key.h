// The instructor's answer key: for every student and exercise, each question's answer, tolerance and the
// slips it recognises (key.json, read back by the grader), and the worked solutions in Markdown (key.md).
// Also the plain-text answer format students fill in (docs/homework.md):
//
//   # comments and blank lines are ignored
//   rectangles.F12 = 0.1234
//   jacobi-gauss-seidel.G1[2] = 3.5
#pragma once

#include <string>
#include <vector>

#include "homework/exercise.h"

namespace rt::homework {

struct StudentExercises {
  std::string id;  // "s01", ...
  std::vector<Exercise> exercises;
};

struct Assignment {
  std::uint64_t seed = 0;
  std::vector<std::string> topics;
  std::vector<StudentExercises> students;
};

// Generates every student's variant of every topic; students are s01 .. sNN (width from the count).
Assignment makeAssignment(const std::vector<std::string>& topics, std::uint64_t seed, int count);
std::string studentId(int index, int count);

// key.json: everything the grader needs, nothing it must recompute.
std::string keyJson(const Assignment& assignment);
// Reads key.json back (questions, tolerances, mistakes, row checks; no statements). Throws InputError naming
// the file and the JSON path of a missing or wrong field.
Assignment parseKeyJson(const std::string& text, const std::string& fileName);

// The worked solutions of all students, Markdown with $...$ maths.
std::string keyMarkdown(const Assignment& assignment);

// The answer file of one student: every question id, followed by its answer when `filled`, left blank
// otherwise (the template handed out).
std::string answersText(const StudentExercises& student, bool filled);

}  // namespace rt::homework
