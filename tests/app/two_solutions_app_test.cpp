// The lesson "Two solutions of one equation" in the app: its pathtrace steps show the path-traced, radiosity
// and two-pass pictures in the step's figures (the same drawing as `radiosity lesson render`), and the paths
// per pixel, changed in the parameter panel as a reader does, retrace them.
#include <gtest/gtest.h>

#include <QImage>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>

#include "app/camera_path_player.h"
#include "app/figures_pane.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app/screenshot.h"
#include "app_test_support.h"
#include "lesson/step_result.h"
#include "support/test_paths.h"

using namespace rt::app;

namespace {

const rt::lesson::StepResult* stepResult(MainWindow& window) {
  const PipelineResult* r = window.result();
  return r && r->stepResult ? static_cast<const rt::lesson::StepResult*>(r->stepResult.get()) : nullptr;
}

}  // namespace

TEST(TwoSolutionsInTheApp, ThePicturesShowInTheStepFigures) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("two-solutions", 0)) << window->lastError().toStdString();
  const auto* r = stepResult(*window);
  ASSERT_NE(r, nullptr);
  ASSERT_TRUE(r->pictures);
  EXPECT_GT(r->pictures->mean, 0);
  const auto pictures = r->pictures;  // the result itself goes with the next step
  EXPECT_EQ(window->figuresPane()->figureCount(), 1);
  // The figure holds pictures, not a blank page or a black frame.
  const QImage figures = window->figuresPane()->grab().toImage();
  const PixelStatistics stats = pixelStatistics(figures);
  EXPECT_GT(stats.distinctColours, 200);
  EXPECT_GT(stats.stdDevLuminance, 10);
  EXPECT_GT(stats.nonBlackFraction, 0.5);
  // A screenshot of the whole window, for a person to look at.
  const std::string png = rt::test::scratchDir("two-solutions-app") + "/step1.png";
  EXPECT_TRUE(grabWindow(*window).save(QString::fromStdString(png)));

  // Every other pathtrace step shows its view, from the same pictures.
  for (int step = 1; step <= 3; ++step) {
    ASSERT_TRUE(window->openLesson("two-solutions", step)) << window->lastError().toStdString();
    EXPECT_EQ(window->figuresPane()->figureCount(), 1) << "step " << step + 1;
    ASSERT_NE(stepResult(*window), nullptr);
    EXPECT_EQ(stepResult(*window)->pictures, pictures) << "step " << step + 1 << " traced them again";
  }
}

TEST(TwoSolutionsInTheApp, MorePathsPerPixelRetraceWithLessNoise) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("two-solutions", 1)) << window->lastError().toStdString();
  ASSERT_NE(stepResult(*window), nullptr);
  const double before = *stepResult(*window)->value("noise.path-traced");
  QWidget* editor = window->parameterPanel()->editor("paths");
  ASSERT_NE(qobject_cast<QSpinBox*>(editor), nullptr);
  test::typeInto(editor, "1024");
  EXPECT_EQ(window->parameterPanel()->parameters().paths, 1024);
  ASSERT_NE(stepResult(*window), nullptr);
  const double after = *stepResult(*window)->value("noise.path-traced");
  // Four times the paths: half the noise.
  EXPECT_NEAR(after / before, 0.5, 0.1);
}

// The step with a camera path: one solve, then the Walkthrough button flies the 3D view through the scene's
// cameras left, above and right, ending on the last.
TEST(TwoSolutionsInTheApp, TheWalkthroughFliesThroughTheScenesCameras) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("two-solutions", 4)) << window->lastError().toStdString();
  CameraPathPlayer* player = window->pathPlayer();
  ASSERT_TRUE(player->isVisible());
  EXPECT_EQ(player->frameCount(), 24);
  EXPECT_EQ(window->figuresPane()->figureCount(), 0) << "the walkthrough is flown, not drawn as frames";
  const auto* r = stepResult(*window);
  ASSERT_NE(r, nullptr);
  const rt::Camera last = r->cameraPath.back();
  const QImage before = window->primaryView()->grab().toImage();
  player->setFramesPerSecond(200);
  QTest::mouseClick(player->button(), Qt::LeftButton);
  EXPECT_TRUE(player->playing());
  EXPECT_TRUE(QTest::qWaitFor([&] { return !player->playing(); }, 10000));
  EXPECT_EQ(player->current(), 23);
  const rt::Camera shown = window->primaryView()->currentCamera();
  EXPECT_LT((shown.position - last.position).norm(), 1e-6 * last.position.norm());
  const QImage after = window->primaryView()->grab().toImage();
  EXPECT_NE(before, after) << "the view moved";
  EXPECT_GT(pixelStatistics(after).nonBlackFraction, 0.5) << "inside the box, not behind a wall";
  // A step without a path hides the button.
  ASSERT_TRUE(window->openLesson("two-solutions", 0));
  EXPECT_FALSE(player->isVisible());
}
