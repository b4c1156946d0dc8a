// The parameter panel under a reader's hands: keys and clicks on the real widgets, then what the reader sees
// (the step's numbers, its text, the window's pixels). One test per kind of widget, and a walk over every
// lesson step that changes each control it offers once.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QTest>
#include <QTextBrowser>
#include <cmath>

#include "app/figures_pane.h"
#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app/screenshot.h"
#include "app_test_support.h"
#include "lesson/step_numbers.h"
#include "lesson/step_result.h"

using namespace rt::app;

namespace {

// What a reader can see of a result: the numbers behind the step, its text, the 3D view and the step's
// figures (not the panel itself, whose widgets show the edit whether or not it took effect).
struct Seen {
  std::string numbers;
  QString text;
  QImage view, figures;
};

Seen look(MainWindow& window) {
  Seen seen;
  const PipelineResult* r = window.result();
  if (r && r->stepResult)
    seen.numbers =
        rt::lesson::stepNumbersJson(*static_cast<const rt::lesson::StepResult*>(r->stepResult.get()));
  if (r && r->B.size() > 0) seen.numbers += " B=" + std::to_string(r->B.sum());
  seen.text = window.textView()->toPlainText();
  seen.view = window.primaryView()->grab().toImage();
  seen.figures = window.figuresPane()->grab().toImage();
  return seen;
}

// Changes the control once, as a reader would: an arrow key in a spin box or combo box, a click on a check
// box, a new value typed into a text field.
void nudge(QWidget* editor, const std::string& key) {
  editor->setFocus();
  if (auto* spin = qobject_cast<QAbstractSpinBox*>(editor)) {
    auto* ints = qobject_cast<QSpinBox*>(spin);
    auto* doubles = qobject_cast<QDoubleSpinBox*>(spin);
    const bool atTop = ints ? ints->value() >= ints->maximum() : doubles->value() >= doubles->maximum();
    QTest::keyClick(spin, atTop ? Qt::Key_Down : Qt::Key_Up);
  } else if (auto* box = qobject_cast<QComboBox*>(editor)) {
    QTest::keyClick(box, box->currentIndex() + 1 < box->count() ? Qt::Key_Down : Qt::Key_Up);
  } else if (auto* check = qobject_cast<QCheckBox*>(editor)) {
    QTest::mouseClick(check, Qt::LeftButton, {}, QPoint(8, check->height() / 2));
  } else if (auto* line = qobject_cast<QLineEdit*>(editor)) {
    const double value = line->text().toDouble();
    QString next;
    if (key == "from")
      next = line->text() == "1" ? "2" : "1";
    else
      next = QString::number(value > 0 ? value * 10 : 1e-3, 'g', 6);
    test::typeInto(line, next);
    return;
  }
  test::waitForApply();
}

// Picks a form-factor method in the panel's combo box by typing its name, as a reader does.
void chooseMethod(MainWindow& window, const char* name) {
  auto* method = qobject_cast<QComboBox*>(window.parameterPanel()->editor("method"));
  ASSERT_NE(method, nullptr);
  method->setFocus();
  QTest::keyClicks(method, name);  // typing selects the item, as in any combo box
  test::waitForApply();
}

}  // namespace

// The light's spin box: typed, the light doubles and so does B, and F is reused.
TEST(ParameterControls, ASpinBoxTypedIntoChangesTheResult) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  const rt::RgbField before = window->result()->B;
  test::typeInto(window->parameterPanel()->editor("light-scale"), "2");
  EXPECT_TRUE(window->result()->B.isApprox(2.0 * before, 1e-4));
  EXPECT_TRUE(window->result()->formFactorsReused);
}

// The hemicube resolution: an integer spin box whose edit recomputes F at the new resolution.
TEST(ParameterControls, TheHemicubeResolutionTakesEffect) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  chooseMethod(*window, "hemicube");
  ASSERT_EQ(window->result()->formFactorMethod, "hemicube");
  const int computed = static_cast<int>(window->result()->formFactorStats.elements);
  test::typeInto(window->parameterPanel()->editor("resolution"), "16");
  EXPECT_EQ(window->parameterPanel()->parameters().resolution.value_or(0), 16);
  EXPECT_FALSE(window->result()->formFactorsReused);
  EXPECT_EQ(static_cast<int>(window->result()->formFactorStats.elements), computed);
  EXPECT_NE(window->result()->formFactorStats.notes.find("16"), std::string::npos)
      << window->result()->formFactorStats.notes;
}

// The form factors' tolerance: a typed field whose 0 reads as the method's own (empty, with that text greyed)
// and whose typed value reaches the quadrature method.
TEST(ParameterControls, TheFormFactorToleranceReachesTheQuadratureMethod) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  chooseMethod(*window, "quadrature");
  ASSERT_EQ(window->result()->formFactorMethod, "quadrature");
  auto* field = qobject_cast<QLineEdit*>(window->parameterPanel()->editor("ff-tolerance"));
  ASSERT_NE(field, nullptr);
  EXPECT_TRUE(field->text().isEmpty());
  EXPECT_EQ(field->placeholderText(), "the method's own");
  EXPECT_NE(window->result()->formFactorStats.notes.find("absolute tolerance 1e-05"), std::string::npos)
      << window->result()->formFactorStats.notes;
  test::typeInto(field, "1e-3");
  EXPECT_EQ(window->parameterPanel()->parameters().formFactorTolerance.value_or(0), 1e-3);
  EXPECT_NE(window->result()->formFactorStats.notes.find("absolute tolerance 0.001"), std::string::npos)
      << window->result()->formFactorStats.notes;
}

// A check box (smooth shading) changes what the view shows, not the numbers.
TEST(ParameterControls, ACheckBoxChangesTheView) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  const Seen before = look(*window);
  nudge(window->parameterPanel()->editor("smooth"), "smooth");
  EXPECT_TRUE(window->parameterPanel()->parameters().smooth);
  EXPECT_NE(look(*window).view, before.view);
}

// A typed value out of range is refused with the table's message, and nothing is recomputed.
TEST(ParameterControls, AValueOutOfRangeIsRefusedWithItsRange) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  const auto* before = window->result();
  test::typeInto(window->parameterPanel()->editor("tolerance"), "5");
  EXPECT_TRUE(window->parameterPanel()->lastRefusal().contains("[1e-15, 0.5]"))
      << window->parameterPanel()->lastRefusal().toStdString();
  EXPECT_EQ(window->result(), before);
}

// Every lesson step, every control it offers, changed once through its widget: the numbers, the text or the
// picture changes. Where nothing can change, the reason is known and checked.
TEST(ParameterControls, EveryControlOfEveryLessonStepTakesEffect) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  LessonLibrary& library = *window->library();
  int changed = 0;
  for (int l = 0; l < static_cast<int>(library.lessons().size()); ++l) {
    const auto& lesson = library.lessons()[static_cast<std::size_t>(l)];
    for (const auto& step : lesson.steps) {
      for (const std::string& key : step.controls) {
        const std::string where = lesson.id + " step " + std::to_string(step.index) + " control " + key;
        ASSERT_TRUE(window->openStep(l, step.index)) << where << ": " << window->lastError().toStdString();
        ParameterPanel* panel = window->parameterPanel();
        ASSERT_TRUE(panel->offers(key)) << where << ": the panel does not offer it";
        QWidget* editor = panel->editor(key);
        ASSERT_NE(editor, nullptr) << where;
        const rt::lesson::StepParameters before = panel->parameters();
        const Seen seen = look(*window);
        nudge(editor, key);
        EXPECT_TRUE(panel->lastRefusal().isEmpty()) << where << ": " << panel->lastRefusal().toStdString();
        EXPECT_TRUE(window->lastError().isEmpty()) << where << ": " << window->lastError().toStdString();
        const Seen after = look(*window);
        const bool differs = after.numbers != seen.numbers || after.text != seen.text ||
                             after.view != seen.view || after.figures != seen.figures;
        // A larger iteration cap changes nothing in a solve that converged before reaching it.
        const PipelineResult* r = window->result();
        const bool convergedBelowCap = key == "iterations" && r && r->status == rt::SolverStatus::Success &&
                                       r->iterations < panel->parameters().iterations.value_or(0);
        // The tests' quick mode caps subdivisions at 3 and hemicube resolutions at 32
        // (lesson::RunOptions::quick): 4 and 5 are both 3 there, 128 and 136 both 32.
        const bool cappedByQuickMode = (key == "subdivide" && before.subdivide.value_or(1) >= 3 &&
                                        panel->parameters().subdivide.value_or(1) >= 3) ||
                                       (key == "resolution" && before.resolution.value_or(0) >= 32 &&
                                        panel->parameters().resolution.value_or(0) >= 32);
        EXPECT_TRUE(differs || convergedBelowCap || cappedByQuickMode)
            << where << ": nothing the reader sees changed";
        changed += differs;
      }
    }
  }
  EXPECT_GT(changed, 20);
}

// A reader who doubles the light sees a brighter room: the automatic exposure is found once for the scene
// and kept, the status line says which exposure is in use, and the text's mean radiosity doubles.
TEST(ParameterControls, ABrighterLightGivesABrighterPicture) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  ASSERT_TRUE(
      window->openScene(QString::fromStdString(RT_SOURCE_DIR "/tests/data/cornell-box-no-camera.obj")));
  auto* view = window->primaryView();
  const QRect area = test::areaOf(window.get(), view);
  const double before = pixelStatistics(grabWindow(*window), area).meanLuminance;
  auto* status = window->findChild<QLabel*>("statusMessage");
  ASSERT_NE(status, nullptr);
  EXPECT_TRUE(status->text().contains("exposure")) << status->text().toStdString();
  test::typeInto(window->parameterPanel()->editor("light-scale"), "2");
  const double after = pixelStatistics(grabWindow(*window), area).meanLuminance;
  EXPECT_GT(after, 1.2 * before) << before << " -> " << after;
  test::typeInto(window->parameterPanel()->editor("light-scale"), "0.5");
  const double dimmer = pixelStatistics(grabWindow(*window), area).meanLuminance;
  EXPECT_LT(dimmer, 0.8 * before) << before << " -> " << dimmer;
}
