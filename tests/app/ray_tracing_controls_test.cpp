// The lesson on ray tracing in the app: the self-intersection epsilon is a number field; typing 0 into it
// brings the shadow acne into the picture and the count, and a proper value takes it away again. The ray
// tree of the recursion step is drawn in the rotatable 3D view and follows the traced pixel.
#include <gtest/gtest.h>

#include <QDoubleSpinBox>
#include <QSpinBox>
#include <QTest>
#include <cmath>

#include "app/figures_pane.h"
#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app_test_support.h"
#include "lesson/step_result.h"

using namespace rt::app;

namespace {

int stepWithFigure(const MainWindow& window, const std::string& figure) {
  const int lesson = window.library()->indexOf("ray-tracing");
  if (lesson < 0) return -1;
  for (const auto& s : window.library()->lessons()[static_cast<std::size_t>(lesson)].steps)
    if (s.figure == figure) return s.index;
  return -1;
}

}  // namespace

TEST(RayTraceControls, EpsilonZeroBringsTheAcneIntoThePictureAndTheNumbers) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const int step = stepWithFigure(*window, "epsilon");
  ASSERT_GE(step, 0);
  ASSERT_TRUE(window->openLesson("ray-tracing", step)) << window->lastError().toStdString();
  ASSERT_EQ(window->figuresPane()->figureCount(), 1);
  auto* epsilon = qobject_cast<QDoubleSpinBox*>(window->parameterPanel()->editor("ray-epsilon"));
  ASSERT_NE(epsilon, nullptr) << "ray-epsilon is offered as a number field";
  EXPECT_LT(test::stepValue(*window, "acne.step"), 1e-3);
  const QImage picture = window->figuresPane()->grab().toImage();

  test::typeInto(epsilon, "0");
  EXPECT_TRUE(window->parameterPanel()->lastRefusal().isEmpty())
      << window->parameterPanel()->lastRefusal().toStdString();
  EXPECT_DOUBLE_EQ(window->parameterPanel()->parameters().rayEpsilon, 0.0);
  EXPECT_DOUBLE_EQ(test::stepValue(*window, "epsilon"), 0.0);
  EXPECT_GT(test::stepValue(*window, "acne.step"), 0.2) << "epsilon 0: the lit points shadow themselves";
  EXPECT_NE(window->figuresPane()->grab().toImage(), picture) << "the figure was not redrawn";

  test::typeInto(epsilon, "0.5");
  EXPECT_LT(test::stepValue(*window, "acne.step"), 1e-3);
  EXPECT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
}

TEST(RayTraceControls, TheRayTreeIsDrawnInThe3DViewAndFollowsThePixel) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const int step = stepWithFigure(*window, "tree");
  ASSERT_GE(step, 0);
  ASSERT_TRUE(window->openLesson("ray-tracing", step)) << window->lastError().toStdString();
  const int rays = window->primaryView()->raySegmentCount();
  EXPECT_EQ(rays, static_cast<int>(test::stepValue(*window, "tree.rays")));
  EXPECT_GT(rays, 2) << "the pixel sees the mirror: a reflected ray and its shadow rays";
  const QImage view = window->primaryView()->grab().toImage();
  auto* depth = qobject_cast<QSpinBox*>(window->parameterPanel()->editor("ray-depth"));
  ASSERT_NE(depth, nullptr);
  test::typeInto(depth, "0");
  EXPECT_EQ(test::stepValue(*window, "tree.reflection"), 0);
  EXPECT_LT(window->primaryView()->raySegmentCount(), rays);
  EXPECT_NE(window->primaryView()->grab().toImage(), view) << "the 3D view did not redraw the tree";
  EXPECT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
}

// The glossy step: the mirrors' gloss exponent is a number field; a smaller q blurs the reflection more, in
// the picture and in the number that measures it, and the rays per pixel are a field that changes the picture
// too.
TEST(RayTraceControls, TheGlossExponentAndTheRaysPerPixelChangeThePicture) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const int step = stepWithFigure(*window, "glossy");
  ASSERT_GE(step, 0);
  ASSERT_TRUE(window->openLesson("ray-tracing", step)) << window->lastError().toStdString();
  auto* gloss = qobject_cast<QDoubleSpinBox*>(window->parameterPanel()->editor("gloss"));
  ASSERT_NE(gloss, nullptr) << "gloss is offered as a number field";
  const double blur = test::stepValue(*window, "gloss-difference");
  EXPECT_GT(blur, 0);
  const QImage picture = window->figuresPane()->grab().toImage();

  test::typeInto(gloss, "4");
  EXPECT_TRUE(window->parameterPanel()->lastRefusal().isEmpty())
      << window->parameterPanel()->lastRefusal().toStdString();
  EXPECT_DOUBLE_EQ(test::stepValue(*window, "gloss"), 4.0);
  EXPECT_GT(test::stepValue(*window, "gloss-difference"), blur) << "q = 4: blurrier than the step's q";
  EXPECT_NE(window->figuresPane()->grab().toImage(), picture) << "the figure was not redrawn";

  auto* rays = qobject_cast<QSpinBox*>(window->parameterPanel()->editor("pixel-samples"));
  ASSERT_NE(rays, nullptr);
  const QImage before = window->figuresPane()->grab().toImage();
  test::typeInto(rays, "1");
  EXPECT_DOUBLE_EQ(test::stepValue(*window, "pixel-samples"), 1.0);
  EXPECT_EQ(test::stepValue(*window, "rays.primary"), test::stepValue(*window, "pixels"));
  EXPECT_NE(window->figuresPane()->grab().toImage(), before) << "the figure was not redrawn";
  EXPECT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
}

// The focus step: the lens's radius and its focus distance are number fields. A radius of 0 is the pinhole,
// and the short block in front of the plane of focus turns sharp, in the picture and in its measured blur;
// focusing on the short block instead turns the order round, the back wall now the blurred one.
TEST(RayTraceControls, TheLensRadiusAndTheFocusDistanceChangeThePictureAndTheBlur) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const int step = stepWithFigure(*window, "focus");
  ASSERT_GE(step, 0);
  ASSERT_TRUE(window->openLesson("ray-tracing", step)) << window->lastError().toStdString();
  auto* aperture = qobject_cast<QDoubleSpinBox*>(window->parameterPanel()->editor("aperture"));
  auto* focus = qobject_cast<QDoubleSpinBox*>(window->parameterPanel()->editor("focus-distance"));
  ASSERT_NE(aperture, nullptr) << "aperture is offered as a number field";
  ASSERT_NE(focus, nullptr) << "focus-distance is offered as a number field";
  const double front = test::stepValue(*window, "focus-difference.short_block");
  const double disc = test::stepValue(*window, "blur-disc.short_block");
  EXPECT_GT(front, 0) << "the short block lies off the plane of focus";
  EXPECT_GT(disc, 1);
  const QImage picture = window->figuresPane()->grab().toImage();

  test::typeInto(aperture, "0");
  EXPECT_TRUE(window->parameterPanel()->lastRefusal().isEmpty())
      << window->parameterPanel()->lastRefusal().toStdString();
  EXPECT_DOUBLE_EQ(window->parameterPanel()->parameters().aperture, 0.0);
  EXPECT_DOUBLE_EQ(test::stepValue(*window, "aperture"), 0.0);
  EXPECT_EQ(test::stepValue(*window, "focus-difference.short_block"), 0.0) << "radius 0 is the pinhole";
  EXPECT_EQ(test::stepValue(*window, "blur-disc.short_block"), 0.0);
  EXPECT_NE(window->figuresPane()->grab().toImage(), picture) << "the figure was not redrawn";

  test::typeInto(aperture, "40");
  EXPECT_DOUBLE_EQ(test::stepValue(*window, "focus-difference.short_block"), front);
  const QImage focusedFar = window->figuresPane()->grab().toImage();
  const double near = test::stepValue(*window, "depth.short_block");
  ASSERT_GT(near, 0);
  test::typeInto(focus, QString::number(std::round(near)));
  EXPECT_TRUE(window->parameterPanel()->lastRefusal().isEmpty())
      << window->parameterPanel()->lastRefusal().toStdString();
  EXPECT_NEAR(test::stepValue(*window, "focus-distance"), near, 1.0);
  EXPECT_LT(test::stepValue(*window, "blur-disc.short_block"), 0.1 * disc) << "the short block is in focus";
  EXPECT_GT(test::stepValue(*window, "focus-difference.back_wall"),
            test::stepValue(*window, "focus-difference.short_block"))
      << "focused near, the back wall blurs instead";
  EXPECT_NE(window->figuresPane()->grab().toImage(), focusedFar) << "the figure was not redrawn";
  EXPECT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
}

// The motion step: how far the short block slides while the shutter is open is a number field. 0 stands it
// still, in the picture and in the streak's length and measured blur; a longer slide blurs more.
TEST(RayTraceControls, TheMotionChangesThePictureAndTheStreak) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const int step = stepWithFigure(*window, "motion");
  ASSERT_GE(step, 0);
  ASSERT_TRUE(window->openLesson("ray-tracing", step)) << window->lastError().toStdString();
  auto* motion = qobject_cast<QDoubleSpinBox*>(window->parameterPanel()->editor("motion"));
  ASSERT_NE(motion, nullptr) << "motion is offered as a number field";
  const double streak = test::stepValue(*window, "motion-pixels.short_block");
  const double blur = test::stepValue(*window, "motion-difference.short_block");
  const double moved = motion->value();
  EXPECT_GT(moved, 0);
  EXPECT_GT(streak, 1);
  EXPECT_GT(blur, 0);
  const QImage picture = window->figuresPane()->grab().toImage();

  test::typeInto(motion, "0");
  EXPECT_TRUE(window->parameterPanel()->lastRefusal().isEmpty())
      << window->parameterPanel()->lastRefusal().toStdString();
  EXPECT_DOUBLE_EQ(window->parameterPanel()->parameters().motion, 0.0);
  EXPECT_EQ(test::stepValue(*window, "motion-pixels.short_block"), 0.0);
  EXPECT_EQ(test::stepValue(*window, "motion-difference.short_block"), 0.0) << "motion 0 stands still";
  const QImage still = window->figuresPane()->grab().toImage();
  EXPECT_NE(still, picture) << "the figure was not redrawn";

  test::typeInto(motion, QString::number(2 * moved));
  EXPECT_NEAR(test::stepValue(*window, "motion-pixels.short_block"), 2 * streak, 1e-6 * streak);
  EXPECT_GT(test::stepValue(*window, "motion-difference.short_block"), blur);
  EXPECT_NE(window->figuresPane()->grab().toImage(), still) << "the figure was not redrawn";
  EXPECT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
}
