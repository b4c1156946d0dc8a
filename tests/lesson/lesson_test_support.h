// Helpers for the lesson tests: loading the shipped lessons, finding a step by its figure name, making sure
// the form-factor methods a test needs are present.
#pragma once

#include <functional>
#include <string>

#include "lesson/lesson.h"
#include "lesson/lesson_loader.h"
#include "lesson/step_result.h"

namespace rt::lesson::test {

LessonFolders repoFolders();
Lesson shippedLesson(const std::string& id);
const Step& stepWithFigure(const Lesson& lesson, const std::string& figure);
// True when the registry has the method; false means the test should be skipped (e.g. exact not built).
bool hasMethod(const std::string& name);
// Registers "analytic" from the closed-form polygon-to-polygon formula when the registry lacks it (unoccluded
// scenes only), so that the runner can be tested before or without the core's method.
void ensureAnalyticMethod();
// A lesson of one step whose text (starting at file line 10) is `text`, as lessons/x.md with this order.
Lesson oneStepLesson(const std::string& text, int order = 4);
// The message of the InputError that `f` throws, or "" when it throws none.
std::string inputErrorOf(const std::function<void()>& f);

// A shipped lesson's step, run as written after `change` to its parameters; its text resolves.
struct RanStep {
  Lesson lesson;
  Step step;
  StepResult result;
  // The step's number `name`; a name it does not compute fails the test and reads NaN.
  double operator[](const std::string& name) const;
};
RanStep runShippedStep(const std::string& lesson, const std::string& figure,
                       const std::function<void(StepParameters&)>& change = {});

}  // namespace rt::lesson::test
