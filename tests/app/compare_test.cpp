// Compare mode's right pane: another solver, form-factor method or mesh, on one camera and one clock.
#include <gtest/gtest.h>

#include <vtkCamera.h>
#include <vtkRenderer.h>
#include <cstdlib>

#include <QApplication>
#include <QColor>
#include <QComboBox>
#include <QFileInfo>
#include <QImage>
#include <QLineEdit>
#include <QSpinBox>
#include <QTest>

#include "app/compare_choice.h"
#include "app/iteration_player.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app/screenshot.h"
#include "app_test_support.h"
#include "support/test_paths.h"
#include "viz/vtk_render.h"

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

// Compare mode's panes are narrower than they are tall: each keeps the step's view angle across its width, so
// both side walls of the Cornell box (red and green) are in view, not just the middle of the room.
TEST(CompareMode, NarrowPanesShowTheWholeRoom) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->resize(1400, 900);
  ASSERT_TRUE(window->openLesson("gathering", 0)) << window->lastError().toStdString();
  window->setCompareMode(true);
  QApplication::processEvents();
  for (SceneView* view : {window->primaryView(), window->secondaryView()}) {
    ASSERT_LT(view->width(), view->height());
    EXPECT_TRUE(view->renderer()->GetActiveCamera()->GetUseHorizontalViewAngle());
    const QImage image = grabWindow(*window).copy(test::areaOf(window.get(), view));
    // The room fills a square across the pane, background above it (a view cropped to the middle of the room
    // has none), and both side walls show.
    const QColor background =
        QColor::fromRgbF(rt::viz::kBackground[0], rt::viz::kBackground[1], rt::viz::kBackground[2]);
    int top = 0, topSamples = 0, red = 0, green = 0, samples = 0;
    for (int y = 0; y < image.height(); y += 2)
      for (int x = 0; x < image.width(); x += 2) {
        const QColor c = image.pixelColor(x, y);
        ++samples;
        red += c.red() > 1.8 * c.green() && c.red() > 1.8 * c.blue() && c.red() > 60;
        green += c.green() > 1.3 * c.red() && c.green() > 1.3 * c.blue() && c.green() > 60;
        if (y < image.height() / 10) {
          ++topSamples;
          top += std::abs(c.red() - background.red()) + std::abs(c.green() - background.green()) +
                     std::abs(c.blue() - background.blue()) <
                 12;
        }
      }
    EXPECT_GT(top, topSamples * 9 / 10) << "background above the room";
    EXPECT_GT(red, samples / 50) << "the red wall";
    EXPECT_GT(green, samples / 50) << "the green wall";
  }
  window->setCompareMode(false);
  QApplication::processEvents();
  EXPECT_GT(window->primaryView()->width(), window->primaryView()->height());
  EXPECT_FALSE(window->primaryView()->renderer()->GetActiveCamera()->GetUseHorizontalViewAngle());
}

// Export in compare mode writes both panes as one figure, at the size asked for: the left pane's mesh at the
// left, the finer one at the right (a coarse and a fine mesh of the same room differ in their pixels).
TEST(CompareMode, ExportWritesBothPanesAsOneFigure) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->show();
  ASSERT_TRUE(window->openScene(QString()));
  window->setCompareChoice(CompareChoice{"", "", "finer"});
  window->setCompareMode(true);
  QApplication::processEvents();
  ASSERT_NE(window->result()->compared, nullptr);
  const std::string folder = rt::test::scratchDir("compare-export");
  for (const char* name : {"both.png", "both.svg", "both.pdf"}) {
    const QString path = QString::fromStdString(folder + "/" + name);
    ASSERT_TRUE(window->exportView(path, QSize(1000, 400))) << window->lastError().toStdString();
    EXPECT_GT(QFileInfo(path).size(), 1000) << name;
  }
  const QImage both(QString::fromStdString(folder + "/both.png"));
  ASSERT_EQ(both.size(), QSize(1000, 400));
  const QImage left = both.copy(0, 0, 500, 400), right = both.copy(500, 0, 500, 400);
  EXPECT_GT(pixelStatistics(left).meanLuminance, 10) << "the left pane is drawn";
  EXPECT_GT(pixelStatistics(right).meanLuminance, 10) << "the right pane is drawn";
  EXPECT_NE(left, right) << "the two panes show their own meshes";
}

// File > Export view (Ctrl+E) asks for the picture's size in the save dialog: typed into its width and height
// fields, it is the size of the file written, of both panes side by side in compare mode and of the one view
// otherwise. The fields start at the size on screen.
TEST(CompareMode, TheExportDialogWritesTheSizeTypedIntoIt) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  ASSERT_TRUE(window->openScene(QString()));
  const std::string folder = rt::test::scratchDir("compare-export-size");
  struct Case {
    bool compare;
    QSize size;
    const char* name;
  };
  for (const Case& c : {Case{true, QSize(1400, 500), "both.png"}, Case{false, QSize(700, 650), "one.png"}}) {
    if (c.compare) window->setCompareChoice(CompareChoice{"", "", "finer"});
    window->setCompareMode(c.compare);
    ASSERT_TRUE(window->waitUntilIdle());
    const QString path = QString::fromStdString(folder + "/" + c.name);
    QFile::remove(path);
    QSize proposed;
    test::whenModal([&](QWidget* dialog) {
      auto* width = dialog->findChild<QSpinBox*>("exportWidth");
      auto* height = dialog->findChild<QSpinBox*>("exportHeight");
      auto* name = dialog->findChild<QLineEdit*>("fileNameEdit");
      if (!width || !height || !name) {
        dialog->close();
        return;
      }
      proposed = QSize(width->value(), height->value());
      for (const auto& [box, value] :
           {std::pair{width, c.size.width()}, std::pair{height, c.size.height()}}) {
        box->setFocus();
        box->selectAll();
        QTest::keyClicks(box, QString::number(value));
      }
      name->setFocus();
      name->setText(path);
      QTest::keyClick(name, Qt::Key_Return);
      if (dialog->isVisible()) dialog->close();
    });
    window->activateWindow();
    QApplication::setActiveWindow(window.get());
    QTest::keyClick(window.get(), Qt::Key_E, Qt::ControlModifier);
    ASSERT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
    EXPECT_EQ(proposed, window->viewExportSize()) << c.name << ": the fields start at the size on screen";
    const QImage image(path);
    ASSERT_FALSE(image.isNull()) << c.name << ": not written (no size fields in the dialog?)";
    EXPECT_EQ(image.size(), c.size) << c.name;
    if (c.compare) {
      const int half = c.size.width() / 2;
      const QImage left = image.copy(0, 0, half, c.size.height());
      const QImage right = image.copy(half, 0, half, c.size.height());
      EXPECT_GT(pixelStatistics(left).meanLuminance, 10) << "the left pane is drawn";
      EXPECT_GT(pixelStatistics(right).meanLuminance, 10) << "the right pane is drawn";
      EXPECT_NE(left, right) << "the two panes show their own meshes";
    }
  }
}

TEST(CompareMode, AStepThatCannotTakeTheComparedSolverSaysSoInTheRightPane) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  // The sampling step measures the stochastic solvers' error: Jacobi has none to measure.
  ASSERT_TRUE(window->openLesson("stochastic", 10)) << window->lastError().toStdString();
  window->setCompareMode(true);
  window->setCompareChoice(CompareChoice{"jacobi", "", ""});
  QApplication::processEvents();
  EXPECT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
  const PipelineResult* r = window->result();
  ASSERT_NE(r, nullptr);
  ASSERT_NE(r->compared, nullptr);
  EXPECT_EQ(r->compared->mesh, r->mesh);
  const std::string caption = window->secondaryView()->caption().toStdString();
  EXPECT_NE(caption.find("Not compared"), std::string::npos) << caption;
  EXPECT_NE(caption.find("jacobi"), std::string::npos) << caption;
}
