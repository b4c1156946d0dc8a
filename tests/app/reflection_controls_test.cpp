// The lesson on reflection in the app: the BRDF's model, Phong's exponent, the specular fraction, the
// anisotropy and the incidence are widgets of the parameter panel, and the ambient light of the local
// picture is one too. Changing each by simulated input redraws the figure and the 3D lobe and changes the
// step's numbers.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QTest>

#include "app/figures_pane.h"
#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app_test_support.h"
#include "lesson/step_result.h"

using namespace rt::app;

namespace {

bool openFigure(MainWindow& window, const std::string& figure) {
  const int lesson = window.library()->indexOf("reflection");
  if (lesson < 0) return false;
  for (const auto& s : window.library()->lessons()[static_cast<std::size_t>(lesson)].steps)
    if (s.figure == figure) return window.openLesson("reflection", s.index) && window.waitUntilIdle(60000);
  return false;
}

struct Pictures {
  QImage figure, view;
};

Pictures grab(MainWindow& window) {
  return {window.figuresPane()->grab().toImage(), window.primaryView()->grab().toImage()};
}

// Types `text` into the number field of `key`, waits for the step to run again, and checks that the figure
// and the 3D view changed.
void typeAndExpectRedraw(MainWindow& window, const char* key, const QString& text, bool viewChanges = true) {
  auto* field = qobject_cast<QDoubleSpinBox*>(window.parameterPanel()->editor(key));
  ASSERT_NE(field, nullptr) << key << " is offered as a number field";
  const Pictures before = grab(window);
  test::typeInto(field, text);
  ASSERT_TRUE(window.waitUntilIdle(60000));
  EXPECT_TRUE(window.parameterPanel()->lastRefusal().isEmpty())
      << window.parameterPanel()->lastRefusal().toStdString();
  const Pictures after = grab(window);
  EXPECT_NE(after.figure, before.figure) << key << ": the figure was not redrawn";
  if (viewChanges) {
    EXPECT_NE(after.view, before.view) << key << ": the 3D view did not change";
  }
  EXPECT_TRUE(window.lastError().isEmpty()) << window.lastError().toStdString();
}

}  // namespace

TEST(ReflectionControls, PhongsExponentFractionAndIncidenceChangeTheLobe) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(openFigure(*window, "phong")) << window->lastError().toStdString();
  const double peak = test::stepValue(*window, "f.peak");
  ASSERT_GT(peak, 0);
  typeAndExpectRedraw(*window, "phong-exponent", "64");
  EXPECT_DOUBLE_EQ(window->parameterPanel()->parameters().phongExponent, 64.0);
  EXPECT_GT(test::stepValue(*window, "f.peak"), 2 * peak) << "a narrower, brighter lobe";
  const double kd = test::stepValue(*window, "kd");
  typeAndExpectRedraw(*window, "specular-fraction", "0.9");
  EXPECT_LT(test::stepValue(*window, "kd"), kd);
  EXPECT_NEAR(test::stepValue(*window, "ks"), 0.9 * test::stepValue(*window, "reflectance"), 1e-12);
  const double albedo = test::stepValue(*window, "albedo");
  typeAndExpectRedraw(*window, "incidence-angle", "80");
  EXPECT_LT(test::stepValue(*window, "albedo"), albedo) << "more of the lobe below the surface";
}

TEST(ReflectionControls, TheModelMenuAndTheAnisotropyChangeTheLobe) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(openFigure(*window, "anisotropic")) << window->lastError().toStdString();
  EXPECT_NEAR(test::stepValue(*window, "alpha-x") / test::stepValue(*window, "alpha-y"), 4.0, 1e-9);
  typeAndExpectRedraw(*window, "anisotropy", "1");
  EXPECT_DOUBLE_EQ(test::stepValue(*window, "alpha-x"), test::stepValue(*window, "alpha-y"));

  auto* model = qobject_cast<QComboBox*>(window->parameterPanel()->editor("brdf-model"));
  ASSERT_NE(model, nullptr) << "brdf-model is offered as a menu";
  ASSERT_EQ(model->currentText().toStdString(), "ward");
  const Pictures before = grab(*window);
  // Up the menu from ward: phong, then mirror.
  model->setFocus();
  QTest::keyClick(model, Qt::Key_Up);
  QTest::keyClick(model, Qt::Key_Up);
  test::waitForApply();
  ASSERT_TRUE(window->waitUntilIdle(60000));
  EXPECT_EQ(window->parameterPanel()->parameters().brdfModel, "mirror");
  EXPECT_DOUBLE_EQ(test::stepValue(*window, "delta"), test::stepValue(*window, "reflectance"))
      << "the mirror's delta";
  const Pictures after = grab(*window);
  EXPECT_NE(after.figure, before.figure);
  EXPECT_NE(after.view, before.view);
}

TEST(ReflectionControls, TheAmbientLightChangesTheLocalPictureOnly) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(openFigure(*window, "phong-local")) << window->lastError().toStdString();
  const double local = test::stepValue(*window, "image.local.mean"),
               radiosity = test::stepValue(*window, "image.radiosity.mean");
  ASSERT_GT(local, 0);
  // The 3D view shows the radiosity solution, which the ambient term does not touch.
  typeAndExpectRedraw(*window, "ambient-light", "3", false);
  EXPECT_DOUBLE_EQ(window->parameterPanel()->parameters().ambientLight, 3.0);
  EXPECT_GT(test::stepValue(*window, "image.local.mean"), local);
  EXPECT_DOUBLE_EQ(test::stepValue(*window, "image.radiosity.mean"), radiosity);
  EXPECT_NEAR(test::stepValue(*window, "ambient"), 3.0, 1e-12);
}
