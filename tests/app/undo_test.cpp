// Undo and redo of parameter changes, as a reader does it: three edits typed into the panel, then Ctrl+Z
// (Edit > Undo) and Ctrl+Shift+Z. Each undo gives back the previous value in its widget and the previous
// result on screen.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QTest>
#include <QTextBrowser>

#include "app/parameter_history.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app/screenshot.h"
#include "app_test_support.h"

using namespace rt::app;

namespace {

double lightBox(MainWindow& window) {
  return qobject_cast<QDoubleSpinBox*>(window.parameterPanel()->editor("light-scale"))->value();
}

// The reader clicks into the step's text (away from the spin box, whose own undo would take Ctrl+Z), then
// presses the keys.
void press(MainWindow& window, Qt::KeyboardModifiers modifiers) {
  // Another test's window on the same X server may have taken the focus meanwhile.
  window.activateWindow();
  QApplication::setActiveWindow(&window);
  QTest::mouseClick(window.textView()->viewport(), Qt::LeftButton);
  QTest::keyClick(&window, Qt::Key_Z, modifiers);
  test::waitForApply();
}

}  // namespace

TEST(Undo, ThreeChangesUndoneAndRedoneWithTheKeys) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  std::vector<rt::RgbField> results{window->result()->B};
  std::vector<double> values{lightBox(*window)};
  for (const char* value : {"2", "3", "0.5"}) {
    test::typeInto(window->parameterPanel()->editor("light-scale"), value);
    results.push_back(window->result()->B);
    values.push_back(lightBox(*window));
  }
  ASSERT_DOUBLE_EQ(values.back(), 0.5);
  ASSERT_TRUE(window->history()->canUndo());
  for (int k = 2; k >= 0; --k) {
    press(*window, Qt::ControlModifier);
    EXPECT_DOUBLE_EQ(lightBox(*window), values[static_cast<std::size_t>(k)]) << "undo to change " << k;
    EXPECT_TRUE(window->result()->B.isApprox(results[static_cast<std::size_t>(k)], 1e-9)) << "undo " << k;
    if (k == 1) {
      // The screenshot of the undone state, for a reader of the test's output to look at.
      QDir().mkpath(RT_BINARY_DIR "/tests/screenshots");
      grabWindow(*window).save(RT_BINARY_DIR "/tests/screenshots/undo-after-three-changes.png");
    }
  }
  EXPECT_FALSE(window->history()->canUndo());
  press(*window, Qt::ControlModifier | Qt::ShiftModifier);
  EXPECT_DOUBLE_EQ(lightBox(*window), values[1]);
  EXPECT_TRUE(window->result()->B.isApprox(results[1], 1e-9));
  // The Edit menu names what it would undo.
  QAction* undo = test::menuAction(*window, "Edit", "Undo light-scale");
  EXPECT_NE(undo, nullptr);
}

// A new step starts with an empty history: Ctrl+Z never reaches into another step.
TEST(Undo, ANewStepStartsAFreshHistory) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("cornell-box", 0));
  test::typeInto(window->parameterPanel()->editor("bounces"), "2");
  EXPECT_TRUE(window->history()->canUndo());
  ASSERT_TRUE(window->nextStep());
  EXPECT_FALSE(window->history()->canUndo());
}
