// While a new step computes, the views that still show the previous step look out of date; an exercise or a
// page of text never waits behind another step's long computation, nor shows that step's view meanwhile.
#include <gtest/gtest.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QLabel>
#include <QTest>

#include "app/lesson_session.h"
#include "app_test_support.h"
#include "lesson/step_result.h"

using namespace rt::app;

namespace {

QLabel* staleCover(MainWindow& window) {
  return window.findChild<QLabel*>("staleCover");
}

}  // namespace

TEST(StaleView, TheViewsAreCoveredWhileANewStepComputes) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow(/*threaded=*/true);
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  ASSERT_TRUE(window->openLesson("shooting", 1));  // a solve: the views are shown
  ASSERT_TRUE(window->waitUntilIdle(60000));
  ASSERT_NE(staleCover(*window), nullptr);
  EXPECT_FALSE(staleCover(*window)->isVisible());
  ASSERT_TRUE(window->nextStep());
  EXPECT_TRUE(staleCover(*window)->isVisible()) << "the previous step's view looked current";
  ASSERT_TRUE(window->waitUntilIdle(60000));
  EXPECT_FALSE(staleCover(*window)->isVisible());
}

// The two-solutions lesson's first step path-traces for seconds; its exercise, opened at once after it,
// shows its own question at once and stays shown when the overtaken computation ends.
TEST(StaleView, AnExerciseNeverWaitsBehindALongStep) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow(/*threaded=*/true);
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  const int lesson = window->library()->indexOf("two-solutions");
  ASSERT_GE(lesson, 0);
  const auto& steps = window->library()->lessons()[static_cast<std::size_t>(lesson)].steps;
  int exercise = -1;
  for (const auto& s : steps)
    if (s.stage == rt::lesson::Stage::Exercise && exercise < 0) exercise = s.index;
  ASSERT_GE(exercise, 0);
  ASSERT_TRUE(window->openStep(lesson, 0));
  QElapsedTimer timer;
  timer.start();
  ASSERT_TRUE(window->openStep(lesson, exercise));
  const qint64 ms = timer.elapsed();
  ASSERT_NE(window->result(), nullptr);
  auto shown = [&] {
    const auto* r = static_cast<const rt::lesson::StepResult*>(window->result()->stepResult.get());
    return r && r->exercise.has_value();
  };
  EXPECT_TRUE(shown()) << "the exercise waited for the path tracer";
  EXPECT_LT(ms, 2000) << ms << " ms";
  EXPECT_FALSE(staleCover(*window)->isVisible());
  ASSERT_TRUE(window->waitUntilIdle(120000));
  EXPECT_TRUE(shown()) << "the overtaken step's result replaced the exercise";
  EXPECT_EQ(window->currentStep(), exercise);
}
