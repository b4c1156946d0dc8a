// Compare mode's right pane: another solver, form-factor method or mesh, on one camera and one clock.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>

#include "app/compare_choice.h"
#include "app/iteration_player.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app_test_support.h"

using namespace rt::app;

TEST(CompareChoice, ScalesTheMeshByHalfOrTwice) {
  rt::MeshOptions count;
  count.mode = rt::MeshOptions::Mode::Count;
  count.count = 4;
  EXPECT_EQ(scaledMesh(count, "finer").count, 8);
  EXPECT_EQ(scaledMesh(count, "coarser").count, 2);
  EXPECT_EQ(scaledMesh(count, "adaptive").count, 4);
  rt::MeshOptions edge;
  edge.mode = rt::MeshOptions::Mode::MaxEdge;
  edge.maxEdge = 100;
  EXPECT_DOUBLE_EQ(scaledMesh(edge, "finer").maxEdge, 50);
  EXPECT_DOUBLE_EQ(scaledMesh(edge, "coarser").maxEdge, 200);
  rt::MeshOptions none;  // one element per patch: finer splits each patch in 2 x 2, coarser stays
  EXPECT_EQ(scaledMesh(none, "finer").mode, rt::MeshOptions::Mode::Count);
  EXPECT_EQ(scaledMesh(none, "finer").count, 2);
  EXPECT_EQ(scaledMesh(none, "coarser").mode, rt::MeshOptions::Mode::None);
  EXPECT_FALSE(CompareChoice{}.changesSomething());
  EXPECT_TRUE((CompareChoice{"", "", "finer"}.changesSomething()));
  EXPECT_FALSE((CompareChoice{"", "", "finer"}.refinesMesh()));
  EXPECT_TRUE((CompareChoice{"", "", "hierarchical"}.refinesMesh()));
}

TEST(CompareChoice, CaptionsNameTheFormFactorMethodWhenThePanesDiffer) {
  PipelineResult left, right;
  left.solverName = right.solverName = "gauss-seidel";
  left.formFactorMethod = "analytic";
  right.formFactorMethod = "hemicube";
  EXPECT_EQ(paneCaption(left, &right), "gauss-seidel, analytic F");
  EXPECT_EQ(paneCaption(right, &left), "gauss-seidel, hemicube F");
  right.formFactorMethod = "analytic";
  EXPECT_EQ(paneCaption(left, &right), "gauss-seidel");  // the same on both sides: not worth the room
  EXPECT_EQ(paneCaption(left), "gauss-seidel");
}

TEST(CompareMode, AHemicubeLessonAgainstAnalyticFormFactorsSaysWhichPaneIsWhich) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("cornell-box", 3)) << window->lastError().toStdString();
  window->setCompareMode(true);
  window->setCompareChoice(CompareChoice{"", "analytic", ""});
  QApplication::processEvents();
  const PipelineResult* r = window->result();
  ASSERT_NE(r, nullptr);
  ASSERT_NE(r->compared, nullptr);
  EXPECT_EQ(r->formFactorMethod, "hemicube");
  EXPECT_EQ(r->compared->formFactorMethod, "analytic");
  EXPECT_NE(window->primaryView()->caption().toStdString().find("hemicube F"), std::string::npos);
  EXPECT_NE(window->secondaryView()->caption().toStdString().find("analytic F"), std::string::npos);
}

TEST(CompareMode, FinerMeshInTheRightPane) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  rt::lesson::StepParameters p = window->parameterPanel()->parameters();
  p.subdivide = 2;
  window->applyParameters(p);
  window->setCompareChoice(CompareChoice{"", "", "finer"});
  window->setCompareMode(true);
  QApplication::processEvents();
  const PipelineResult* r = window->result();
  ASSERT_NE(r, nullptr);
  ASSERT_NE(r->compared, nullptr);
  ASSERT_NE(r->compared->mesh, nullptr);
  // Twice the subdivision of every patch: four times the elements, the same solver and light.
  EXPECT_EQ(r->compared->mesh->size(), 4 * r->mesh->size());
  EXPECT_EQ(r->compared->solverName, r->solverName);
  EXPECT_EQ(window->secondaryView()->viewData().B.rows(), static_cast<long>(r->compared->mesh->size()));
  EXPECT_NE(window->secondaryView()->caption().toStdString().find(std::to_string(r->compared->mesh->size())),
            std::string::npos);
}

TEST(CompareMode, HierarchicalMeshInTheRightPaneOfALesson) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("cornell-box", 3)) << window->lastError().toStdString();
  window->setCompareMode(true);
  window->setCompareChoice(CompareChoice{"", "", "hierarchical"});
  QApplication::processEvents();
  EXPECT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
  const PipelineResult* r = window->result();
  ASSERT_NE(r, nullptr);
  ASSERT_NE(r->compared, nullptr);
  ASSERT_NE(r->compared->mesh, nullptr);
  EXPECT_NE(r->compared->mesh, r->mesh);
  // The refined solution lights the room: the light's power reaches the walls.
  EXPECT_GT(r->compared->B.maxCoeff(), 0.0);
  EXPECT_EQ(window->secondaryView()->viewData().B.rows(), static_cast<long>(r->compared->mesh->size()));
  // Its pane has no recorded iterations: scrubbing the shared clock keeps its final radiosity.
  window->player()->setCurrent(0);
  EXPECT_TRUE(window->secondaryView()->viewData().B.isApprox(r->compared->B));
}

TEST(CompareMode, TheMeshChoiceIsOfferedInThePanel) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  auto* box = window->findChild<QComboBox*>("compareMesh");
  ASSERT_NE(box, nullptr);
  for (const std::string& choice : compareMeshChoices())
    EXPECT_GE(box->findText(QString::fromStdString(choice)), 0) << choice;
  box->setCurrentText("coarser");
  EXPECT_EQ(window->compareChoice().mesh, "coarser");
}
