// Exercise steps in the app: the question appears with one field per answer; an answer typed into a field
// with the keyboard and Enter is checked (right, or wrong with the slip named); a hint and the worked
// solution are one click away; other steps hide the panel.
#include <gtest/gtest.h>

#include <QApplication>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QTest>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "app/exercise_panel.h"
#include "app/lesson_session.h"
#include "app/lesson_text_view.h"
#include "app_test_support.h"
#include "homework/plain_text.h"

using namespace rt::app;

namespace {

// Every lesson ends with its exercises: the first of them, or the first conceptual question.
int firstExercise(MainWindow& window, int lesson, bool conceptual = false) {
  const auto& steps = window.library()->lessons()[static_cast<std::size_t>(lesson)].steps;
  for (std::size_t k = 0; k < steps.size(); ++k)
    if (steps[k].stage == rt::lesson::Stage::Exercise && steps[k].choices.empty() != conceptual)
      return static_cast<int>(k);
  return -1;
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
  EXPECT_TRUE(panel->instruction().contains("Type your answers")) << panel->instruction().toStdString();
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

// The shooting lesson's first exercise (Southwell): every field filled (every other one wrong), Check, Page
// Down to the next step and Page Up back: the answers and what Check said are there again; and in a window
// opened anew, as after a restart. A wrong answer is said too high, never with the key's value.
TEST(AppExercise, AnswersStayWithTheirStepAcrossStepsAndRestarts) {
  RT_REQUIRE_DISPLAY();
  QSettings().remove("exercises");
  std::map<std::string, QString> typed, verdicts;
  QString summary;
  int step = -1;
  {
    auto window = rt::app::test::makeWindow();
    window->show();
    const int shooting = window->library()->indexOf("shooting");
    ASSERT_GE(shooting, 0);
    step = firstExercise(*window, shooting);
    ASSERT_TRUE(window->openLesson("shooting", step));
    ASSERT_TRUE(window->waitUntilIdle(20000));
    ExercisePanel* panel = window->exercisePanel();
    ASSERT_TRUE(panel->exercise().has_value());
    const rt::homework::Exercise& e = *panel->exercise();
    ASSERT_EQ(e.topic, "southwell");
    const std::size_t n = e.questions.size();
    ASSERT_GE(n, 6u);
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
    EXPECT_EQ(summary, QString("%1 of %2 right").arg((n + 1) / 2).arg(n));
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
    ASSERT_EQ(window->currentStep(), step + 1);
    QTest::keyClick(focus(), Qt::Key_PageUp);
    ASSERT_TRUE(window->waitUntilIdle(20000));
    ASSERT_EQ(window->currentStep(), step);
    for (const auto& [id, text] : typed) {
      EXPECT_EQ(panel->field(id)->text(), text) << id;
      EXPECT_EQ(panel->verdict(id), verdicts[id]) << id;
    }
    EXPECT_EQ(panel->summary(), summary);
    window->close();
  }
  auto window = rt::app::test::makeWindow();
  ASSERT_TRUE(window->openLesson("shooting", step));
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

// A conceptual question: one radio button per choice under the line that says how to answer; a wrong choice
// clicked and checked is said wrong with its own explanation, the right one is said right, Show solution
// gives the answer with every explanation, and the choice is kept across steps.
TEST(AppExercise, AChoiceClickedIsCheckedWithItsExplanation) {
  RT_REQUIRE_DISPLAY();
  QSettings().remove("exercises");
  auto window = rt::app::test::makeWindow();
  window->show();
  const int lesson = window->library()->indexOf("form-factor");
  ASSERT_GE(lesson, 0);
  const int step = firstExercise(*window, lesson, true);
  ASSERT_GE(step, 0);
  ASSERT_TRUE(window->openLesson("form-factor", step));
  ASSERT_TRUE(window->waitUntilIdle(20000));
  ExercisePanel* panel = window->exercisePanel();
  ASSERT_TRUE(panel->isVisible());
  ASSERT_TRUE(panel->exercise().has_value());
  // A copy: the panel holds a new exercise after the reader leaves the step and comes back.
  const rt::homework::Question q = panel->exercise()->questions.front();
  ASSERT_GE(q.choices.size(), 3u);
  EXPECT_TRUE(panel->instruction().contains("Pick one answer")) << panel->instruction().toStdString();
  EXPECT_EQ(panel->field(q.id), nullptr) << "no text field for a choice";
  const int right = static_cast<int>(q.answer);
  const int wrong = right == 1 ? 2 : 1;
  const rt::homework::Mistake* explanation = nullptr;
  for (const rt::homework::Mistake& m : q.mistakes)
    if (static_cast<int>(m.value) == wrong) explanation = &m;
  ASSERT_NE(explanation, nullptr);
  ASSERT_NE(panel->choice(wrong), nullptr);
  EXPECT_EQ(panel->choice(wrong)->text(), wrong == 1 ? "(a)" : "(b)");
  EXPECT_EQ(panel->choiceText(wrong),
            QString::fromStdString(rt::homework::plainText(q.choices[static_cast<std::size_t>(wrong - 1)])));
  QTest::mouseClick(panel->choice(wrong), Qt::LeftButton, {}, QPoint(8, panel->choice(wrong)->height() / 2));
  EXPECT_TRUE(panel->choice(wrong)->isChecked());
  QTest::mouseClick(panel->findChild<QPushButton*>("checkAnswers"), Qt::LeftButton);
  EXPECT_EQ(panel->verdict(q.id),
            QString::fromStdString(rt::homework::plainText("wrong: " + explanation->name)));
  EXPECT_EQ(panel->summary(), "0 of 1 right");
  if (const char* shot = std::getenv("RT_CHOICE_SCREENSHOT")) {
    window->findChild<rt::app::LessonTextView*>()->waitUntilShown();
    window->grab().save(shot);
  }
  // The right one by a click on its text, not its button.
  QLabel* rightText = nullptr;
  for (QLabel* label : panel->findChildren<QLabel*>())
    if (label->text() == panel->choiceText(right)) rightText = label;
  ASSERT_NE(rightText, nullptr);
  QTest::mouseClick(rightText, Qt::LeftButton);
  EXPECT_TRUE(panel->choice(right)->isChecked());
  EXPECT_FALSE(panel->choice(wrong)->isChecked());
  QTest::mouseClick(panel->findChild<QPushButton*>("checkAnswers"), Qt::LeftButton);
  EXPECT_EQ(panel->verdict(q.id), "right");
  EXPECT_EQ(panel->summary(), "1 of 1 right");
  QTest::mouseClick(panel->findChild<QPushButton*>("showSolution"), Qt::LeftButton);
  EXPECT_TRUE(panel->notes().contains("The answer is")) << panel->notes().toStdString();
  for (const rt::homework::Mistake& m : q.mistakes)
    EXPECT_TRUE(panel->notes().contains(QString::fromStdString(m.name))) << m.name;
  // Away and back: the choice and the verdict are kept.
  ASSERT_TRUE(window->openLesson("form-factor", 0));
  ASSERT_TRUE(window->waitUntilIdle(20000));
  EXPECT_FALSE(panel->isVisible());
  ASSERT_TRUE(window->openLesson("form-factor", step));
  ASSERT_TRUE(window->waitUntilIdle(20000));
  ASSERT_NE(panel->choice(right), nullptr);
  EXPECT_TRUE(panel->choice(right)->isChecked());
  EXPECT_EQ(panel->verdict(q.id), "right");
  QSettings().remove("exercises");
}

}  // namespace
