// Long work is visible: while a step computes on the worker thread, the progress strip is on screen and names
// the phase it is in (the mesh, the form factors with the method that runs, the solve).
#include <gtest/gtest.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QTest>
#include <QThread>
#include <set>

#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app/progress_strip.h"
#include "app_test_support.h"

using namespace rt::app;

TEST(ProgressPhases, TheStripShowsThePhaseAndTheMethodThatRuns) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow(/*threaded=*/true, /*quick=*/false);
  ASSERT_TRUE(window->openScene(QString()));
  ASSERT_TRUE(window->waitUntilIdle());
  // A finer mesh: a job of a few seconds, started by typing, as a reader starts it.
  QWidget* subdivide = window->parameterPanel()->editor("subdivide");
  subdivide->setFocus();
  QTest::mouseClick(subdivide, Qt::LeftButton);
  QTest::keyClick(subdivide, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(subdivide, "12");
  QTest::keyClick(subdivide, Qt::Key_Return);
  std::set<std::string> stages;
  bool shownWhileBusy = false;
  QElapsedTimer timer;
  timer.start();
  // The panel applies the edit after its pause; then the job runs until the window is idle again.
  while ((window->busy() || timer.elapsed() < 600) && timer.elapsed() < 120000) {
    QApplication::processEvents(QEventLoop::AllEvents, 20);
    if (window->busy() && timer.elapsed() > 100) {
      shownWhileBusy = shownWhileBusy || window->progressStrip()->isVisible();
      stages.insert(window->progressStrip()->text().toStdString());
    }
    QThread::msleep(5);
  }
  ASSERT_GT(timer.elapsed(), 1000) << "the job was too short to show anything";
  EXPECT_TRUE(shownWhileBusy);
  bool formFactors = false;
  for (const std::string& s : stages)
    formFactors = formFactors || s.find("form factors (quadrature)") != std::string::npos;
  std::string all;
  for (const std::string& s : stages) all += s + " | ";
  EXPECT_TRUE(formFactors) << all;
  EXPECT_FALSE(window->progressStrip()->isVisible());
}
