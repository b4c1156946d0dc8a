// The session survives a restart: the lesson and step, the reader's parameters, the opened scene and the
// camera. A long step (a benchmark) is not recomputed on its own at the next start: the reader presses
// Compute.
#include <gtest/gtest.h>

#include <QApplication>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTest>
#include <QTextBrowser>

#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app_test_support.h"

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
