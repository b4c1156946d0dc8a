// Every lesson opens and every step computes and shows, without an error or a Qt warning, walking the book
// with the Next action from the first step to the last.
#include <gtest/gtest.h>

#include <QTextBrowser>
#include <algorithm>

#include "app/lesson_session.h"
#include "app/scene_view.h"
#include "app_test_support.h"
#include "core/formfactor/formfactor_method.h"

using namespace rt::app;

namespace {

bool usesExact(const rt::lesson::Step& step) {
  const auto& p = step.parameters;
  return p.method == "exact" || p.reference == "exact" ||
         std::find(p.methods.begin(), p.methods.end(), "exact") != p.methods.end();
}

}  // namespace

TEST(LessonWalk, EveryStepOfEveryLessonOpensWithoutErrorOrWarning) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  LessonLibrary& library = *window->library();
  for (const auto& error : library.errors()) ADD_FAILURE() << "lesson does not load: " << error;
  ASSERT_FALSE(library.lessons().empty()) << "no lessons in " << library.folders().lessons;
  int totalSteps = 0;
  for (const auto& lesson : library.lessons()) totalSteps += static_cast<int>(lesson.steps.size());

  const auto methods = rt::formFactorMethodNames();
  const bool exactBuilt = std::find(methods.begin(), methods.end(), "exact") != methods.end();
  test::takeWarnings();
  ASSERT_TRUE(window->openStep(0, 0)) << window->lastError().toStdString();
  int visited = 0;
  do {
    ++visited;
    const auto& lesson = library.lessons()[window->currentLesson()];
    const std::string where = lesson.id + " step " + std::to_string(window->currentStep() + 1);
    const auto& step = lesson.steps[window->currentStep()];
    if (!exactBuilt && usesExact(step)) {
      // Without the CGAL library the step says so clearly, and the rest of the book still works.
      EXPECT_TRUE(window->lastError().contains("not included in this build")) << where;
      EXPECT_TRUE(window->textView()->toPlainText().contains("could not be computed")) << where;
      test::takeWarnings();
      continue;
    }
    EXPECT_TRUE(window->lastError().isEmpty()) << where << ": " << window->lastError().toStdString();
    ASSERT_NE(window->result(), nullptr) << where;
    EXPECT_TRUE(window->result()->note.empty()) << where << ": " << window->result()->note;
    const QString text = window->textView()->toPlainText();
    EXPECT_FALSE(text.contains("{{")) << where << ": unresolved placeholder";
    EXPECT_FALSE(text.contains("Computing...")) << where;
    if (lesson.steps[window->currentStep()].stage != rt::lesson::Stage::Text) {
      EXPECT_TRUE(window->primaryView()->hasMesh()) << where;
    }
    const QStringList warnings = test::takeWarnings();
    EXPECT_TRUE(warnings.isEmpty()) << where << ": " << warnings.join("\n").toStdString();
  } while (window->nextStep());
  EXPECT_EQ(visited, totalSteps);
}
