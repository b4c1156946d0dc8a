// The lesson on measuring light in the app: the patch whose solid angle the first figure measures moves when
// the reader changes its distance in the parameter panel, and the picture and the number follow.
#include <gtest/gtest.h>

#include <QDoubleSpinBox>
#include <QTest>

#include "app/figures_pane.h"
#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app_test_support.h"

using namespace rt::app;

TEST(RadiometryControls, MovingThePatchChangesItsSolidAngleAndItsPicture) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const int lesson = window->library()->indexOf("measuring-light");
  ASSERT_GE(lesson, 0);
  int step = -1;
  for (const auto& s : window->library()->lessons()[static_cast<std::size_t>(lesson)].steps)
    if (s.figure == "solid-angle") step = s.index;
  ASSERT_GE(step, 0);
  ASSERT_TRUE(window->openLesson("measuring-light", step)) << window->lastError().toStdString();
  ASSERT_EQ(window->figuresPane()->figureCount(), 1);
  auto* distance = qobject_cast<QDoubleSpinBox*>(window->parameterPanel()->editor("patch-distance"));
  ASSERT_NE(distance, nullptr) << "patch-distance is offered as a number field";
  const double before = test::stepValue(*window, "solid-angle");
  const double approxBefore = test::stepValue(*window, "solid-angle.approx");
  ASSERT_GT(before, 0);
  const QImage picture = window->figuresPane()->grab().toImage();
  const QImage view = window->primaryView()->grab().toImage();

  test::typeInto(distance, "2");
  EXPECT_TRUE(window->parameterPanel()->lastRefusal().isEmpty())
      << window->parameterPanel()->lastRefusal().toStdString();
  EXPECT_DOUBLE_EQ(window->parameterPanel()->parameters().patchDistance, 2.0);
  const double after = test::stepValue(*window, "solid-angle");
  // Twice as far: about a quarter of the solid angle (exactly a quarter for the small-patch formula).
  EXPECT_LT(after, 0.3 * before);
  EXPECT_NEAR(test::stepValue(*window, "solid-angle.approx"), approxBefore / 4, 1e-12);
  EXPECT_NE(window->figuresPane()->grab().toImage(), picture) << "the figure was not redrawn";
  EXPECT_NE(window->primaryView()->grab().toImage(), view) << "the 3D view did not move the patch";
  EXPECT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
}
