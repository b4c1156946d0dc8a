// Computations run off the GUI thread: the window stays responsive while one runs, and cancelling keeps the
// previous result on screen.
#include <gtest/gtest.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QPushButton>
#include <QStatusBar>
#include <QTest>
#include <filesystem>

#include "app/main_window.h"
#include "app/parameter_panel.h"
#include "app/progress_strip.h"
#include "app/scene_view.h"
#include "app_test_support.h"
#include "support/test_paths.h"

using namespace rt::app;

TEST(Cancel, CancelledComputationKeepsThePreviousResult) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow(/*threaded=*/true);
  ASSERT_TRUE(window->openScene(QString()));
  rt::lesson::StepParameters p = window->parameterPanel()->parameters();
  p.subdivide = 2;
  window->applyParameters(p);
  ASSERT_TRUE(window->waitUntilIdle());
  const PipelineResult* previous = window->result();
  ASSERT_NE(previous, nullptr);
  const auto previousMesh = previous->mesh;
  const rt::RgbField previousB = previous->B;

  // Something long: a fine mesh and a high hemicube resolution.
  p.subdivide = 24;
  p.method = "hemicube";
  p.resolution = 512;
  window->applyParameters(p);
  ASSERT_TRUE(window->busy());
  // The GUI thread is free: events are processed while the worker computes.
  QElapsedTimer timer;
  timer.start();
  int ticks = 0;
  while (timer.elapsed() < 300) {
    QApplication::processEvents();
    ++ticks;
  }
  EXPECT_GT(ticks, 10);
  window->cancelComputation();
  ASSERT_TRUE(window->waitUntilIdle(60000));
  EXPECT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
  ASSERT_NE(window->result(), nullptr);
  EXPECT_EQ(window->result()->mesh, previousMesh);
  EXPECT_TRUE(window->result()->B.isApprox(previousB));
  EXPECT_TRUE(window->primaryView()->viewData().B.isApprox(previousB));

  // Still usable: a new computation completes.
  p.subdivide = 1;
  p.resolution = 32;
  window->applyParameters(p);
  ASSERT_TRUE(window->waitUntilIdle());
  ASSERT_NE(window->result(), nullptr);
  EXPECT_NE(window->result()->mesh, previousMesh);
}

TEST(Cancel, ProgressStripShowsTheJobAndItsButtonCancels) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow(/*threaded=*/true);
  ASSERT_TRUE(window->openScene(QString()));
  ASSERT_TRUE(window->waitUntilIdle());
  EXPECT_FALSE(window->progressStrip()->isVisible());
  const auto previousMesh = window->result()->mesh;
  // Presenter mode hides the status bar, but not while something runs: the class sees it and can stop it.
  window->setPresenterMode(true);
  rt::lesson::StepParameters p = window->parameterPanel()->parameters();
  p.subdivide = 24;
  p.method = "hemicube";
  p.resolution = 512;
  QElapsedTimer sinceStart;
  sinceStart.start();
  window->applyParameters(p);
  ASSERT_TRUE(window->busy());
  // Not at once (a short job would only flash it), but after half a second.
  QApplication::processEvents();
  EXPECT_FALSE(window->progressStrip()->isVisible());
  while (!window->progressStrip()->isVisible() && sinceStart.elapsed() < 5000) QApplication::processEvents();
  ASSERT_TRUE(window->busy());
  EXPECT_TRUE(window->progressStrip()->isVisible());
  EXPECT_GE(sinceStart.elapsed(), ProgressStrip::kShowDelayMs - 10);
  EXPECT_TRUE(window->statusBar()->isVisible());
  QTest::mouseClick(window->progressStrip()->cancelButton(), Qt::LeftButton);
  ASSERT_TRUE(window->waitUntilIdle(60000));
  EXPECT_FALSE(window->progressStrip()->isVisible());
  EXPECT_FALSE(window->statusBar()->isVisible());
  EXPECT_EQ(window->result()->mesh, previousMesh);
  window->setPresenterMode(false);
}

TEST(Cancel, AShortJobDoesNotFlashTheStrip) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow(/*threaded=*/true);
  ASSERT_TRUE(window->openScene(QString()));
  ASSERT_TRUE(window->waitUntilIdle());
  // A brighter light reuses F: a solve of a few milliseconds.
  rt::lesson::StepParameters p = window->parameterPanel()->parameters();
  p.lightScale = 2;
  QElapsedTimer timer;
  timer.start();
  window->applyParameters(p);
  bool shown = false;
  while (window->busy() && timer.elapsed() < 60000) {
    shown = shown || window->progressStrip()->isVisible();
    QApplication::processEvents(QEventLoop::AllEvents, 5);
  }
  ASSERT_LT(timer.elapsed(), ProgressStrip::kShowDelayMs) << "the job was too long for this test";
  EXPECT_FALSE(shown);
  EXPECT_FALSE(window->progressStrip()->isVisible());
}

TEST(Cancel, LessonFigureExportRunsInTheBackgroundAndStopsOnCancel) {
  RT_REQUIRE_DISPLAY();
  const std::string dir = rt::test::scratchDir("app-export-cancel");
  auto window = test::makeWindow(/*threaded=*/true);
  ASSERT_TRUE(window->openLesson("cornell-box", 0));
  ASSERT_TRUE(window->waitUntilIdle());
  ASSERT_TRUE(window->exportAllFigures(QString::fromStdString(dir)));
  // It returned at once: the steps are computed on a worker thread, with the strip showing.
  EXPECT_TRUE(window->exportingFigures());
  EXPECT_TRUE(window->progressStrip()->active());
  // Cancelled before the GUI thread drew anything: no figure is written, and the window says so.
  window->cancelFigureExport();
  QElapsedTimer timer;
  timer.start();
  while (window->exportingFigures() && timer.elapsed() < 60000) QApplication::processEvents();
  ASSERT_FALSE(window->exportingFigures());
  EXPECT_FALSE(window->progressStrip()->active());
  EXPECT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 0);
  // The window is still usable: the next step computes.
  ASSERT_TRUE(window->nextStep());
  ASSERT_TRUE(window->waitUntilIdle());
  EXPECT_EQ(window->currentStep(), 1);
}
