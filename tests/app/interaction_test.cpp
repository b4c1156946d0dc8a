// The reader's interactions: keyboard stepping, the iteration replay and its chart, linked selection between
// the views and the matrix, parameter changes (a light change re-solves without recomputing F), compare and
// presenter modes, and a remembered position.
#include <gtest/gtest.h>

#include <vtkCamera.h>
#include <vtkRenderer.h>
#include <QApplication>
#include <QComboBox>
#include <QMenuBar>
#include <QSettings>
#include <QSpinBox>
#include <QTest>
#include <QTextBrowser>

#include "app/iteration_player.h"
#include "app/lesson_session.h"
#include "app/matrix_view.h"
#include "app/parameter_panel.h"
#include "app/residual_chart.h"
#include "app/scene_view.h"
#include "app_test_support.h"

using namespace rt::app;

namespace {

int lessonIndex(MainWindow& w, const std::string& id) {
  return w.library()->indexOf(id);
}

}  // namespace

TEST(Interaction, KeysStepForwardAndBack) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const int cornell = lessonIndex(*window, "cornell-box");
  ASSERT_GE(cornell, 0);
  ASSERT_TRUE(window->openStep(cornell, 0));
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  QTest::keyClick(window.get(), Qt::Key_Right);
  EXPECT_EQ(window->currentStep(), 1);
  QTest::keyClick(window.get(), Qt::Key_PageDown);
  EXPECT_EQ(window->currentStep(), 2);
  QTest::keyClick(window.get(), Qt::Key_Left);
  EXPECT_EQ(window->currentStep(), 1);
  QTest::keyClick(window.get(), Qt::Key_PageUp);
  EXPECT_EQ(window->currentStep(), 0);
  EXPECT_EQ(window->currentLesson(), cornell);
  // Back from a lesson's first step goes to the previous lesson's last step.
  if (cornell > 0) {
    QTest::keyClick(window.get(), Qt::Key_Left);
    EXPECT_EQ(window->currentLesson(), cornell - 1);
    EXPECT_EQ(window->currentStep(),
              static_cast<int>(window->library()->lessons()[cornell - 1].steps.size()) - 1);
  }
}

TEST(Interaction, ReplayShowsEachRecordedIteration) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString())) << window->lastError().toStdString();
  rt::lesson::StepParameters p = window->parameterPanel()->parameters();
  p.solver = "jacobi";
  p.subdivide = 2;
  window->applyParameters(p);
  const PipelineResult* r = window->result();
  ASSERT_NE(r, nullptr);
  ASSERT_GT(r->history.size(), 3u);
  IterationPlayer* player = window->player();
  EXPECT_EQ(player->iterationCount(), static_cast<int>(r->history.size()));
  EXPECT_EQ(player->current(), player->iterationCount() - 1);
  player->setCurrent(0);
  EXPECT_TRUE(window->primaryView()->viewData().B.isApprox(r->history[0].B));
  EXPECT_EQ(window->residualChart()->pointsShown(0), 1);
  player->next();
  EXPECT_EQ(player->current(), 1);
  EXPECT_TRUE(window->primaryView()->viewData().B.isApprox(r->history[1].B));
  EXPECT_EQ(window->residualChart()->pointsShown(0), 2);
  // Jacobi's residual falls from one iteration to the next in this closed, well-conditioned box.
  EXPECT_LT(r->history.back().residual, r->history.front().residual);
  // Playing advances the clock.
  player->setSpeed(100);
  player->setCurrent(0);
  player->play();
  // The clock ticks on the event loop: give it time on a busy machine.
  for (int waited = 0; waited < 5000 && player->current() == 0; waited += 50) QTest::qWait(50);
  player->pause();
  EXPECT_GT(player->current(), 0);
}

TEST(Interaction, LinkedSelectionBetweenViewAndMatrix) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  SceneView* view = window->primaryView();
  // The centre of the Cornell box view is the back wall (or a block): some element.
  const int picked = view->pickElement(QPoint(view->width() / 2, view->height() / 2));
  ASSERT_GE(picked, 0);
  emit view->elementPicked(picked);
  EXPECT_EQ(view->highlighted(), std::vector<int>{picked});
  const auto selected = window->matrixView()->selectionModel()->selectedIndexes();
  ASSERT_FALSE(selected.isEmpty());
  EXPECT_EQ(selected.first().row(), picked);
  // A matrix cell names two elements: both are highlighted.
  emit window->matrixView()->elementsSelected(3, 7);
  EXPECT_EQ(view->highlighted(), (std::vector<int>{3, 7}));
}

TEST(Interaction, LightChangeResolvesWithoutRecomputingFormFactors) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  const auto* before = window->result();
  ASSERT_NE(before, nullptr);
  ASSERT_NE(before->F, nullptr);
  const auto F = before->F;
  const rt::RgbField B = before->B;
  const std::size_t materials = before->scene->materials.size();
  test::typeInto(window->parameterPanel()->editor("light-scale"), "2");
  const auto* after = window->result();
  EXPECT_TRUE(after->formFactorsReused);
  EXPECT_EQ(after->F.get(), F.get());
  // Linear in E: twice the light, twice the radiosity.
  EXPECT_TRUE(after->B.isApprox(2.0 * B, 1e-4));
  // A reflectance change also keeps F.
  test::typeInto(window->parameterPanel()->editor("reflectance"), "0.2");
  EXPECT_GT(window->result()->scene->materials.size(), materials);  // the surface got its own material
  EXPECT_TRUE(window->result()->formFactorsReused);
  EXPECT_EQ(window->result()->F.get(), F.get());
}

TEST(Interaction, LessonLightChangeUsesTheFormFactorCache) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const int cornell = lessonIndex(*window, "cornell-box");
  ASSERT_GE(cornell, 0);
  ASSERT_TRUE(window->openStep(cornell, 3));
  const int computed = window->library()->formFactorComputations();
  rt::lesson::StepParameters p = window->parameterPanel()->parameters();
  p.lightScale = 3.0;
  window->applyParameters(p);
  EXPECT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
  EXPECT_EQ(window->library()->formFactorComputations(), computed);
}

TEST(Interaction, CompareModeSharesCameraAndIterationClock) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  rt::lesson::StepParameters p = window->parameterPanel()->parameters();
  p.solver = "gauss-seidel";
  p.subdivide = 2;
  window->applyParameters(p);
  window->setCompareMode(true);  // the right pane solves with Jacobi
  QApplication::processEvents();
  const PipelineResult* r = window->result();
  ASSERT_NE(r, nullptr);
  ASSERT_NE(r->compared, nullptr);
  EXPECT_TRUE(window->secondaryView()->isVisible());
  EXPECT_EQ(r->compared->solverName, "jacobi");
  // One clock: iteration 2 in both panes.
  window->player()->setCurrent(1);
  EXPECT_TRUE(window->primaryView()->viewData().B.isApprox(r->history[1].B));
  EXPECT_TRUE(window->secondaryView()->viewData().B.isApprox(r->compared->history[1].B));
  // One camera: moving the left view moves the right one.
  vtkCamera* left = window->primaryView()->renderer()->GetActiveCamera();
  left->Azimuth(25);
  emit window->primaryView()->cameraInteraction();
  double a[3], b[3];
  left->GetPosition(a);
  window->secondaryView()->renderer()->GetActiveCamera()->GetPosition(b);
  for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(a[k], b[k]);
  window->setCompareMode(false);
  EXPECT_FALSE(window->secondaryView()->isVisible());
}

TEST(Interaction, PresenterModeEnlargesFontsAndHidesChrome) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  const double normalSize = QApplication::font().pointSizeF();
  window->setPresenterMode(true);
  QApplication::processEvents();
  EXPECT_GT(QApplication::font().pointSizeF(), normalSize * 1.4);
  EXPECT_FALSE(window->menuBar()->isVisible());
  EXPECT_EQ(QApplication::palette().color(QPalette::Base), QColor(0, 0, 0));
  window->setPresenterMode(false);
  QApplication::processEvents();
  EXPECT_DOUBLE_EQ(QApplication::font().pointSizeF(), normalSize);
  EXPECT_TRUE(window->menuBar()->isVisible());
}

TEST(Interaction, RemembersTheLastPosition) {
  RT_REQUIRE_DISPLAY();
  {
    auto window = test::makeWindow();
    const int cornell = lessonIndex(*window, "cornell-box");
    ASSERT_GE(cornell, 0);
    ASSERT_TRUE(window->openStep(cornell, 2));
  }
  auto window = test::makeWindow();
  ASSERT_TRUE(window->start()) << window->lastError().toStdString();
  EXPECT_EQ(window->currentLesson(), lessonIndex(*window, "cornell-box"));
  EXPECT_EQ(window->currentStep(), 2);
  QSettings().clear();
}

TEST(Interaction, AStepOfTextGetsTheWholeWidth) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("hemicube", 0)) << window->lastError().toStdString();
  EXPECT_FALSE(window->viewsShown());  // no empty grey view beside the text
  QApplication::processEvents();       // the splitter gives the space away at the next layout pass
  EXPECT_GT(window->textView()->width(), window->width() / 3);
  ASSERT_TRUE(window->nextStep());
  EXPECT_TRUE(window->viewsShown());
  EXPECT_TRUE(window->primaryView()->hasMesh());
}

TEST(Interaction, ARowOfFormFactorsComesWithItsColourBar) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("hemicube", 1)) << window->lastError().toStdString();
  EXPECT_TRUE(window->primaryView()->showsColourBar());  // values of F are read off the bar
  ASSERT_TRUE(window->openLesson("cornell-box", 3)) << window->lastError().toStdString();
  EXPECT_FALSE(window->primaryView()->showsColourBar());  // radiosity is the colour itself
}

// Every form-factor method in the parameter panel (and compare mode's list) says what it computes as its
// tooltip; the samples box says what a sample is for each method.
TEST(Interaction, FormFactorMethodsExplainThemselves) {
  auto panel = std::make_unique<ParameterPanel>();
  QComboBox* methods = nullptr;
  for (QComboBox* box : panel->findChildren<QComboBox*>())
    if (box->findText("hybrid") >= 0) methods = box;
  ASSERT_NE(methods, nullptr);
  for (int k = 0; k < methods->count(); ++k)
    EXPECT_FALSE(methods->itemData(k, Qt::ToolTipRole).toString().isEmpty())
        << methods->itemText(k).toStdString();
  EXPECT_TRUE(methods->itemData(methods->findText("hybrid"), Qt::ToolTipRole).toString().contains("rays"));
  bool samplesExplained = false;
  for (QSpinBox* box : panel->findChildren<QSpinBox*>())
    samplesExplained |= box->toolTip().contains("per 1 % of");
  EXPECT_TRUE(samplesExplained);
}

// A form-factor method the step does not let the reader change is shown as the one the step used: the
// hemicube lesson's occlusion step computes with the hemicube, not with the default the step never names.
TEST(Interaction, TheParameterPanelShowsTheMethodTheStepUsed) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openStep(lessonIndex(*window, "hemicube"), 4)) << window->lastError().toStdString();
  QComboBox* methods = nullptr;
  for (QComboBox* box : window->parameterPanel()->findChildren<QComboBox*>())
    if (box->findText("hybrid") >= 0) methods = box;
  ASSERT_NE(methods, nullptr);
  EXPECT_EQ(methods->currentText().toStdString(), "hemicube");
  EXPECT_FALSE(methods->isEnabled());
}

// A scene the reader opens computes its form factors with the default method (quadrature), as the CLI
// does; the method box says where analytic-visibility is biased.
TEST(Interaction, AnOpenedSceneUsesTheDefaultFormFactorMethod) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString())) << window->lastError().toStdString();
  QApplication::processEvents();
  EXPECT_EQ(window->parameterPanel()->parameters().method, rt::defaultFormFactorMethod());
  const PipelineResult* r = window->result();
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->formFactorMethod, "quadrature");
  QComboBox* methods = nullptr;
  for (QComboBox* box : window->parameterPanel()->findChildren<QComboBox*>())
    if (box->findText("hybrid") >= 0) methods = box;
  ASSERT_NE(methods, nullptr);
  const int visibility = methods->findText("analytic-visibility");
  ASSERT_GE(visibility, 0);
  EXPECT_TRUE(methods->itemData(visibility, Qt::ToolTipRole).toString().contains("biased"));
}
