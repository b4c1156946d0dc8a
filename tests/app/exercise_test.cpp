// Exercise steps in the app: the question appears with one field per answer; an answer typed into a field
// with the keyboard and Enter is checked (right, or wrong with the slip named); a hint and the worked
// solution are one click away; other steps hide the panel.
#include <gtest/gtest.h>

#include <QLineEdit>
#include <QPushButton>
#include <QTest>
#include <cstdio>
#include <cstdlib>

#include "app/exercise_panel.h"
#include "app/lesson_session.h"
#include "app/lesson_text_view.h"
#include "app_test_support.h"

using namespace rt::app;

namespace {

// The last two steps of every lesson are exercises: open the first of them.
int firstExercise(MainWindow& window, int lesson) {
  const auto& steps = window.library()->lessons()[static_cast<std::size_t>(lesson)].steps;
  return static_cast<int>(steps.size()) - 2;
}

void typeAnswer(MainWindow& window, QLineEdit* field, double value) {
  // Under parallel tests another window may hold the focus: take it back before typing.
  window.activateWindow();
  (void)QTest::qWaitForWindowActive(&window, 2000);
  field->setFocus();
  QTest::mouseClick(field, Qt::LeftButton);
  QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
  char text[40];
  std::snprintf(text, sizeof text, "%.10g", value);
  QTest::keyClicks(field, text);
  QTest::keyClick(field, Qt::Key_Return);
}

TEST(AppExercise, AnAnswerTypedIntoTheFieldIsChecked) {
  RT_REQUIRE_DISPLAY();
  auto window = rt::app::test::makeWindow();
  window->show();
  const int lesson = window->library()->indexOf("form-factor");
  ASSERT_GE(lesson, 0);
  ASSERT_TRUE(window->openLesson("form-factor", firstExercise(*window, lesson)));
  ASSERT_TRUE(window->waitUntilIdle(20000));
  ExercisePanel* panel = window->exercisePanel();
  ASSERT_TRUE(panel->isVisible());
  ASSERT_TRUE(panel->exercise().has_value());
  const rt::homework::Exercise& e = *panel->exercise();
  EXPECT_EQ(e.topic, "rectangles");
  EXPECT_TRUE(window->textView()->toPlainText().contains("(rectangle 1 to 2)"));
  const rt::homework::Question& f12 = e.questions[0];
  const rt::homework::Question& f21 = e.questions[1];
  // The right value for F12, the slip "F_21 given for F_12" for F21's field... and a word for nothing.
  typeAnswer(*window, panel->field(f12.id), f12.answer);
  EXPECT_EQ(panel->verdict(f12.id), "right");
  EXPECT_EQ(panel->field(f12.id)->text().toDouble(), std::stod(panel->field(f12.id)->text().toStdString()));
  if (!f21.mistakes.empty()) {
    typeAnswer(*window, panel->field(f21.id), f21.mistakes.front().value);
    EXPECT_TRUE(panel->verdict(f21.id).contains("likely mistake")) << panel->verdict(f21.id).toStdString();
    EXPECT_EQ(panel->summary(), "1 of 2 right");
  }
  typeAnswer(*window, panel->field(f21.id), f21.answer);
  EXPECT_EQ(panel->verdict(f21.id), "right");
  EXPECT_EQ(panel->summary(), "2 of 2 right");
  if (const char* shot = std::getenv("RT_EXERCISE_SCREENSHOT")) window->grab().save(shot);
  // Hint and solution.
  QTest::mouseClick(panel->findChild<QPushButton*>("showSolution"), Qt::LeftButton);
  // It goes under the step's text, and its maths is typeset there with the lesson's.
  auto* text = window->findChild<rt::app::LessonTextView*>();
  ASSERT_NE(text, nullptr);
  EXPECT_TRUE(text->toPlainText().contains("Worked solution"));
  EXPECT_TRUE(text->toPlainText().contains(QString::fromStdString(e.solution.front())));
  const auto maths = text->mathsState();
  EXPECT_TRUE(maths.ready);
  EXPECT_TRUE(maths.errors.isEmpty()) << maths.errors.join("\n").toStdString();
  EXPECT_GT(maths.katexNodes, 0);
  if (const char* shot = std::getenv("RT_SOLUTION_SCREENSHOT")) {
    text->waitUntilShown();
    window->grab().save(shot);
  }
  // A step that is not an exercise hides the panel.
  ASSERT_TRUE(window->openLesson("form-factor", 0));
  ASSERT_TRUE(window->waitUntilIdle(20000));
  EXPECT_FALSE(panel->isVisible());
}

}  // namespace
