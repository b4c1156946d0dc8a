// Computations run off the GUI thread: the window stays responsive while one runs, and cancelling keeps the
// previous result on screen.
#include <gtest/gtest.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QTest>

#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app_test_support.h"

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
