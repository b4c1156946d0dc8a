// A step's figures are drawn with its computation, on the worker thread, and the window shows those images:
// after Page Down to a step computed ahead, and after a control changed through its widget. The window's
// thread only puts the images on screen, so it answers while the figures are drawn.
#include <gtest/gtest.h>

#include <QAbstractSpinBox>
#include <QApplication>
#include <QElapsedTimer>
#include <QTest>
#include <QTimer>
#include <algorithm>
#include <cstdio>

#include "app/figures_pane.h"
#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app/step_figures.h"
#include "app_test_support.h"

using namespace rt::app;

namespace {

// The figures on screen are the ones the step's job drew (the same files), not drawn again here.
void expectFiguresFromTheJob(const MainWindow& window, const char* when) {
  const PipelineResult* r = window.result();
  ASSERT_NE(r, nullptr) << when;
  ASSERT_NE(r->figures, nullptr) << when << ": the job drew no figures";
  EXPECT_TRUE(r->figures->error.isEmpty()) << when << ": " << r->figures->error.toStdString();
  EXPECT_GT(window.figuresPane()->figureCount(), 0) << when;
  EXPECT_EQ(window.figuresPane()->files(), r->figures->files) << when;
}

}  // namespace

TEST(StepFigures, AreDrawnWithTheStepOffTheWindowsThread) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow(/*threaded=*/true);
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  // "Solid angle and the steradian", then "When the patch is too close": a figure each, no other view.
  ASSERT_TRUE(window->openLesson("measuring-light", 1)) << window->lastError().toStdString();
  ASSERT_TRUE(window->waitUntilIdle(120000));
  expectFiguresFromTheJob(*window, "an opened step");

  // The next step was computed ahead, its figure with it: Page Down shows that figure.
  ASSERT_TRUE(window->waitUntilPrefetched(120000));
  QTest::keyClick(window.get(), Qt::Key_PageDown);
  ASSERT_TRUE(window->waitUntilIdle(120000));
  ASSERT_EQ(window->currentStep(), 2);
  expectFiguresFromTheJob(*window, "a step computed ahead");

  // A control changed through its widget: the step computes again and its job draws the new figure, while
  // the window's thread keeps answering (a 5 ms timer measures its longest silence).
  ASSERT_TRUE(window->waitUntilPrefetched(120000));
  ParameterPanel* panel = window->parameterPanel();
  ASSERT_TRUE(panel->offers("patch-distance"));
  auto* spin = qobject_cast<QAbstractSpinBox*>(panel->editor("patch-distance"));
  ASSERT_NE(spin, nullptr);
  const QStringList before = window->figuresPane()->files();
  QElapsedTimer clock;
  clock.start();
  qint64 last = 0, longest = 0;
  QTimer ticks;
  QObject::connect(&ticks, &QTimer::timeout, [&] {
    longest = std::max(longest, clock.elapsed() - last);
    last = clock.elapsed();
  });
  ticks.start(5);
  spin->setFocus();
  QTest::keyClick(spin, Qt::Key_Up);
  panel->applyNow();
  ASSERT_TRUE(window->waitUntilIdle(120000));
  ticks.stop();
  expectFiguresFromTheJob(*window, "a control change");
  EXPECT_NE(window->figuresPane()->files(), before) << "the figure was not drawn again";
  RecordProperty("longest_silence_ms", static_cast<int>(longest));
  std::printf("the window's longest silence while the step and its figure were computed: %lld ms\n",
              static_cast<long long>(longest));
}
