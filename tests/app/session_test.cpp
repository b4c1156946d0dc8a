// The session survives a restart: the lesson and step, the reader's parameters, the opened scene and the
// camera. A long step (a benchmark) is not recomputed on its own at the next start: the reader presses
// Compute.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTest>
#include <QTextBrowser>

#include "app/figures_pane.h"
#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app/step_result_cache.h"
#include "app_test_support.h"
#include "support/test_paths.h"

using namespace rt::app;

namespace {

int lessonIndex(MainWindow& window, const std::string& id) {
  return window.library()->indexOf(id);
}

}  // namespace

TEST(Session, LessonStepParametersAndCameraComeBack) {
  RT_REQUIRE_DISPLAY();
  QSettings().clear();
  rt::Camera camera;
  {
    auto window = test::makeWindow();
    ASSERT_TRUE(window->openLesson("cornell-box", 0));
    window->activateWindow();
    QApplication::setActiveWindow(window.get());
    QTest::keyClick(window.get(), Qt::Key_Right);  // step 2
    ASSERT_EQ(window->currentStep(), 1);
    test::typeInto(window->parameterPanel()->editor("bounces"), "3");
    QTest::mouseClick(window->textView()->viewport(), Qt::LeftButton);
    QTest::keyClick(window.get(), Qt::Key_7);  // the top view
    camera = window->primaryView()->currentCamera();
    window->close();
  }
  auto window = test::makeWindow();
  ASSERT_TRUE(window->start()) << window->lastError().toStdString();
  EXPECT_EQ(window->currentLesson(), lessonIndex(*window, "cornell-box"));
  EXPECT_EQ(window->currentStep(), 1);
  EXPECT_EQ(qobject_cast<QSpinBox*>(window->parameterPanel()->editor("bounces"))->value(), 3);
  ASSERT_NE(window->result(), nullptr);
  EXPECT_EQ(window->result()->history.size(), 4u) << "B after 0..3 bounces";
  const rt::Camera restored = window->primaryView()->currentCamera();
  EXPECT_LT((restored.position - camera.position).norm(), 1e-6 * camera.position.norm() + 1e-9);
  EXPECT_LT((restored.up - camera.up).norm(), 1e-6);
  QSettings().clear();
}

TEST(Session, AnOpenedSceneComesBack) {
  RT_REQUIRE_DISPLAY();
  QSettings().clear();
  const QString squares = QString::fromStdString(RT_SOURCE_DIR "/scenes/parallel-squares.json");
  {
    auto window = test::makeWindow();
    ASSERT_TRUE(window->openScene(squares));
    test::typeInto(window->parameterPanel()->editor("subdivide"), "2");
    window->close();
  }
  auto window = test::makeWindow();
  ASSERT_TRUE(window->start()) << window->lastError().toStdString();
  ASSERT_NE(window->result(), nullptr);
  EXPECT_EQ(window->result()->scene->patches.size(), 2u);
  EXPECT_EQ(window->result()->mesh->size(), 8u) << "2 x 2 elements on each square";
  QSettings().clear();
}

TEST(Session, ABenchmarkWaitsForTheReaderAfterARestart) {
  RT_REQUIRE_DISPLAY();
  QSettings().clear();
  {
    QSettings settings;
    settings.setValue("position/lesson", "runtime-error-lab");
    settings.setValue("position/step", 0);
    settings.setValue("session/mode", "lesson");
  }
  auto window = test::makeWindow(/*threaded=*/true);
  ASSERT_TRUE(window->start()) << window->lastError().toStdString();
  EXPECT_EQ(window->currentLesson(), lessonIndex(*window, "runtime-error-lab"));
  EXPECT_TRUE(window->computationDeferred());
  EXPECT_FALSE(window->busy()) << "the benchmark started on its own";
  EXPECT_EQ(window->result(), nullptr);
  EXPECT_TRUE(window->textView()->toPlainText().contains("Compute this step"));
  auto* compute = window->findChild<QPushButton*>("computeButton");
  ASSERT_NE(compute, nullptr);
  ASSERT_TRUE(compute->isVisible());
  QTest::mouseClick(compute, Qt::LeftButton);
  EXPECT_TRUE(window->busy() || window->result());
  window->cancelComputation();
  window->waitUntilIdle();
  EXPECT_FALSE(compute->isVisible());
  QSettings().clear();
}

TEST(Session, ALongStepShowsWhatItShowedLastTimeAfterARestart) {
  RT_REQUIRE_DISPLAY();
  QSettings().clear();
  const QString timing = "timing/hemicube/1";  // step 0 is the introduction
  int figures = 0;
  QString numbersShown;
  {
    // The step counts as long (it took 10 s last time): its result is kept when it is computed.
    QSettings().setValue(timing, 10000);
    auto window = test::makeWindow();
    ASSERT_TRUE(window->openLesson("hemicube", 1));
    ASSERT_TRUE(window->waitUntilIdle());
    figures = window->figuresPane()->figureCount();
    ASSERT_GT(figures, 0) << window->lastError().toStdString();
    numbersShown = window->textView()->toPlainText();
  }
  QSettings().setValue(timing, 10000);  // as if it had taken that long again
  auto window = test::makeWindow(/*threaded=*/true);
  ASSERT_TRUE(window->start()) << window->lastError().toStdString();
  EXPECT_TRUE(window->computationDeferred());
  EXPECT_TRUE(window->showingKeptResult());
  EXPECT_FALSE(window->busy()) << "the step was computed again on its own";
  EXPECT_EQ(window->result(), nullptr);
  // The same figures and the text with its numbers, dated, with the way to recompute.
  EXPECT_EQ(window->figuresPane()->figureCount(), figures);
  const QString text = window->textView()->toPlainText();
  EXPECT_TRUE(text.contains("kept from then")) << text.toStdString();
  const QString firstLine = numbersShown.section('\n', 2, 2);
  EXPECT_TRUE(text.contains(firstLine)) << firstLine.toStdString() << "\n---\n" << text.toStdString();
  auto* compute = window->findChild<QPushButton*>("computeButton");
  ASSERT_NE(compute, nullptr);
  EXPECT_TRUE(compute->isVisible());
  // No empty 3D view beside the kept figures: the view shows a scene or is not there.
  EXPECT_FALSE(window->primaryView()->isVisible() && !window->primaryView()->hasMesh())
      << "an empty 3D view beside the kept result";
  QTest::qWait(100);
  window->grab().save(QString::fromStdString(rt::test::scratchDir("app-session") + "/kept-result.png"));
  // Computing the step brings the 3D view back, with the scene in it.
  QTest::mouseClick(compute, Qt::LeftButton);
  ASSERT_TRUE(window->waitUntilIdle());
  EXPECT_FALSE(window->showingKeptResult());
  EXPECT_TRUE(window->primaryView()->isVisible());
  EXPECT_TRUE(window->primaryView()->hasMesh());
  QSettings().clear();
  QDir(StepResultCache().folder()).removeRecursively();
}
