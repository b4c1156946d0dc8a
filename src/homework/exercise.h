// One homework exercise as data: the statement a student reads, the data files it comes with, the questions
// with their answers and tolerances, the worked solution an instructor (or the lesson's "reveal") shows, and
// the wrong answers that typical slips produce, so that the grader can name the slip instead of only saying
// "wrong". Generators (topic_table.h) fill it; the handout writer, the key, the grader and the lessons read
// it.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "homework/figure.h"

namespace rt::homework {

// A wrong answer that a recognised slip produces, e.g. F_ji given for F_ij.
struct Mistake {
  std::string name;  // what the student likely did, as feedback says it
  double value = 0;
};

struct Question {
  std::string id;     // unique within the exercise: "F12", "B1[2]" ... (answer files write "topic.id")
  std::string label;  // what is asked, Markdown with $...$ maths
  double answer = 0;
  double tolerance = 0;  // |submitted - answer| <= tolerance is right
  bool integer = false;  // counts, indices, yes/no (1/0): tolerance 0.5
  std::vector<Mistake> mistakes;
  // A multiple-choice question: the choices as the reader sees them (Markdown), the answer is the 1-based
  // index of the right one, and each wrong choice is a mistake whose name explains why it is wrong.
  std::vector<std::string> choices;
};

// A closed-room row of F: the terms the student derived plus the given ones must sum to 1. When a submitted
// value is wrong and breaks the sum, the feedback says so.
struct RowCheck {
  std::string row;                                    // e.g. "row 1 (the floor)"
  std::vector<std::pair<std::string, double>> terms;  // question id, how many times it appears in the row
  double known = 0;                                   // the sum of the given entries
};

// A matrix (or vector) handed out with the exercise, written as CSV, Matrix Market and NPY.
struct DataFile {
  std::string name;  // file stem, e.g. "F"
  Eigen::MatrixXd matrix;
};

struct Exercise {
  std::string topic;  // the topic's id (topic_table.h)
  int student = 0;    // 0 for a lesson's exercise
  std::uint64_t seed = 0;
  std::string title;
  std::string statement;  // Markdown with $...$ maths
  std::string hint;
  std::vector<std::string> solution;  // worked steps, each a Markdown paragraph with every intermediate value
  std::vector<Question> questions;
  std::vector<RowCheck> rowChecks;
  std::vector<DataFile> data;
  std::optional<Figure> figure;
  // The numbers the statement was written from, by name (a lesson's placeholders, the tests' inputs).
  std::map<std::string, double> given;
  std::string sceneJson;  // the geometry as a scene file, when the exercise has one
  std::string sceneObj;

  const Question* find(const std::string& id) const;
};

// Number formatting shared by statements, solutions and keys: `digits` significant digits, no trailing zeros.
std::string num(double value, int digits = 4);
// The LaTeX for a row vector (x_1, ..., x_n) with `digits` significant digits.
std::string vectorLatex(const Eigen::VectorXd& v, int digits = 4);
// A small matrix as a LaTeX bmatrix.
std::string matrixLatex(const Eigen::MatrixXd& m, int digits = 4);

// A Markdown table of `m` with a first column k = 1, 2, ... and the given column headings (Markdown).
std::string markdownTable(const Eigen::MatrixXd& m, const std::vector<std::string>& columns, int digits = 4);

// The tolerance of a computed real answer: `relative` of its size, at least `absolute`.
double tolerance(double answer, double relative, double absolute);
// Keeps only the mistakes that the tolerance can tell apart from the answer (and from each other's names).
void pruneMistakes(Question& q);

}  // namespace rt::homework
