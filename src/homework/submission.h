// Reading what a student handed in, in any of the documented forms (docs/homework.md), never throwing: every
// problem becomes a message naming the file and line, and whatever could be read is still graded.
//   <submissions>/<student>.txt or <student>/answers.txt   "topic.question = number" lines
//   <submissions>/<student>.csv or <student>/answers.csv   "topic.question,number" rows (header optional)
//   <submissions>/<student>/<topic>.npy                    float64 array, the topic's answers in order
#pragma once

#include <map>
#include <string>
#include <vector>

#include "homework/answer_key.h"

namespace rt::homework {

struct Submission {
  std::vector<std::string> files;        // what was read
  std::map<std::string, double> values;  // "topic.question" -> number
  std::vector<std::string> problems;     // "file:line: ..." messages
  bool found() const { return !files.empty(); }
};

// Text or CSV answers (`csv` selects the separator); unknown ids and malformed lines become problems.
void readAnswerText(const std::string& text, const std::string& file, bool csv, const StudentExercises& key,
                    Submission& into);
// One topic's answers as an NPY array of as many numbers as it has questions (NaN = not answered).
void readAnswerNpy(const std::string& bytes, const std::string& file, const Exercise& exercise,
                   Submission& into);

// Everything `student` handed in under `folder`.
Submission readSubmission(const std::string& folder, const StudentExercises& student);

}  // namespace rt::homework
