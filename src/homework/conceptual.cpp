#include "homework/conceptual.h"

namespace rt::homework {

std::string choiceLetter(std::size_t index) {
  return std::string("(") + static_cast<char>('a' + index) + ")";
}

Exercise conceptualExercise(const std::string& title, const std::vector<Choice>& choices) {
  Exercise e;
  e.topic = kConceptualTopic;
  e.title = title;
  Question q;
  q.id = "choice";
  q.label = "your choice";
  q.integer = true;
  q.tolerance = 0.5;
  std::string right;
  std::vector<std::string> wrong;
  for (std::size_t k = 0; k < choices.size(); ++k) {
    const Choice& c = choices[k];
    q.choices.push_back(c.text);
    // "(b) The choice. Why.": a choice that ends without a full stop gets one.
    const char last = c.text.empty() ? '.' : c.text.back();
    const std::string line =
        choiceLetter(k) + " " + c.text + (last == '.' || last == '?' || last == '!' ? " " : ". ") + c.because;
    if (c.right) {
      q.answer = static_cast<double>(k + 1);
      right = "The answer is " + line;
    } else {
      q.mistakes.push_back({c.because, static_cast<double>(k + 1)});
      wrong.push_back("Not " + line);
    }
  }
  e.hint =
      "Each wrong choice contradicts something this lesson shows or derives: rule them out one at a time.";
  e.solution = {right};
  e.solution.insert(e.solution.end(), wrong.begin(), wrong.end());
  e.given["choices"] = static_cast<double>(choices.size());
  e.questions.push_back(std::move(q));
  return e;
}

std::string answerInstruction(const Exercise& exercise, Frame frame) {
  const bool choice = !exercise.questions.empty() && !exercise.questions.front().choices.empty();
  if (frame == Frame::App)
    return choice ? "Pick one answer and press Check; the hint and the worked solution are one click away."
                  : "Type your answers into the fields and press Check; the hint and the worked solution are "
                    "one click away.";
  return "*The answers and the worked solution are in the appendix, \"Answers to the exercises\".*";
}

}  // namespace rt::homework
