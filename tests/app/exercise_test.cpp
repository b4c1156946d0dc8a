// Exercise steps in the app: the question appears with one field per answer; an answer typed into a field
// with the keyboard and Enter is checked (right, or wrong with the slip named); a hint and the worked
// solution are one click away; other steps hide the panel.
#include <gtest/gtest.h>

#include <QApplication>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QTest>
#include <cstdio>
#include <cstdlib>
#include <map>

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

// The Cornell box lesson, step 5: all 18 fields filled (every other one wrong), Check, Page Down to the
// next step and Page Up back: the answers and what Check said are there again; and in a window opened anew,
// as after a restart. A wrong answer is said too high, never with the key's value.
TEST(AppExercise, AnswersStayWithTheirStepAcrossStepsAndRestarts) {
  RT_REQUIRE_DISPLAY();
  QSettings().remove("exercises");
  std::map<std::string, QString> typed, verdicts;
  QString summary;
  {
    auto window = rt::app::test::makeWindow();
    window->show();
    ASSERT_GE(window->library()->indexOf("cornell-box"), 0);
    ASSERT_TRUE(window->openLesson("cornell-box", 4));
    ASSERT_TRUE(window->waitUntilIdle(20000));
    ExercisePanel* panel = window->exercisePanel();
    ASSERT_TRUE(panel->exercise().has_value());
    const rt::homework::Exercise& e = *panel->exercise();
    ASSERT_EQ(e.questions.size(), 18u);
    window->activateWindow();
    (void)QTest::qWaitForWindowActive(window.get(), 2000);
    for (std::size_t k = 0; k < e.questions.size(); ++k) {
      const rt::homework::Question& q = e.questions[k];
      char text[40];
      std::snprintf(text, sizeof text, "%.10g", k % 2 ? q.answer * 1.5 + 1 : q.answer);
      QLineEdit* field = panel->field(q.id);
      field->setFocus();
      QTest::keyClicks(field, text);
      typed[q.id] = text;
    }
    QTest::mouseClick(panel->findChild<QPushButton*>("checkAnswers"), Qt::LeftButton);
    summary = panel->summary();
    EXPECT_EQ(summary, "9 of 18 right");
    for (const rt::homework::Question& q : e.questions) verdicts[q.id] = panel->verdict(q.id);
    const rt::homework::Question& wrong = e.questions[1];
    EXPECT_TRUE(verdicts[wrong.id].contains("too high")) << verdicts[wrong.id].toStdString();
    EXPECT_FALSE(verdicts[wrong.id].contains("key")) << verdicts[wrong.id].toStdString();
    EXPECT_FALSE(verdicts[wrong.id].contains(QString::number(wrong.answer, 'g', 6)))
        << verdicts[wrong.id].toStdString();

    // The keys go where the reader's focus is (the Check button), as the reader presses them.
    auto focus = [&window] {
      return QApplication::focusWidget() ? QApplication::focusWidget() : window.get();
    };
    QTest::keyClick(focus(), Qt::Key_PageDown);
    ASSERT_TRUE(window->waitUntilIdle(20000));
    ASSERT_EQ(window->currentStep(), 5);
    QTest::keyClick(focus(), Qt::Key_PageUp);
    ASSERT_TRUE(window->waitUntilIdle(20000));
    ASSERT_EQ(window->currentStep(), 4);
    for (const auto& [id, text] : typed) {
      EXPECT_EQ(panel->field(id)->text(), text) << id;
      EXPECT_EQ(panel->verdict(id), verdicts[id]) << id;
    }
    EXPECT_EQ(panel->summary(), summary);
    window->close();
  }
  auto window = rt::app::test::makeWindow();
  ASSERT_TRUE(window->openLesson("cornell-box", 4));
  ASSERT_TRUE(window->waitUntilIdle(20000));
  ExercisePanel* panel = window->exercisePanel();
  for (const auto& [id, text] : typed) {
    ASSERT_NE(panel->field(id), nullptr) << id;
    EXPECT_EQ(panel->field(id)->text(), text) << id;
    EXPECT_EQ(panel->verdict(id), verdicts[id]) << id;
  }
  EXPECT_EQ(panel->summary(), summary);
  QSettings().remove("exercises");
}

}  // namespace
