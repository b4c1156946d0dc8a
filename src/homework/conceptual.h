// A conceptual question: multiple choice, declared in a lesson (docs/lesson-format.md, the ```question
// block), with an explanation for every choice. It becomes an Exercise with one question whose answer is the
// index of the right choice and whose mistakes are the wrong choices, named by their explanations, so that
// the app's Check, the book's questions and the appendix's answers treat it as they treat a numeric exercise.
#pragma once

#include <string>
#include <vector>

#include "homework/exercise.h"

namespace rt::homework {

// The topic id of every conceptual exercise (it is not a row of the topic table: nothing is drawn).
inline constexpr const char* kConceptualTopic = "conceptual";

struct Choice {
  std::string text;     // what the reader picks, Markdown with $...$ maths
  std::string because;  // why it is right, or why it is wrong
  bool right = false;
};

// Exactly one choice is right (the parser checks it); the id of the single question is "choice".
Exercise conceptualExercise(const std::string& title, const std::vector<Choice>& choices);

// "(a)", "(b)", ... for the 0-based index.
std::string choiceLetter(std::size_t index);

// The exercise frame's line that says how to answer: the app's under the fields, the book's under the
// questions. Lessons do not repeat it.
enum class Frame { App, Book };
std::string answerInstruction(const Exercise& exercise, Frame frame);

}  // namespace rt::homework
