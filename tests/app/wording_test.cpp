// Counts in the words a reader expects ("1 bounce", "3 iterations") and the end of a stochastic solve called
// what it is ("noise level reached"), seen where the reader sees them: the status line after a click or a
// key.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QLabel>
#include <QSpinBox>
#include <QTest>
#include <QTextBrowser>

#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app/wording.h"
#include "app_test_support.h"

using namespace rt::app;

namespace {

QString statusLine(MainWindow& window) {
  auto* label = window.findChild<QLabel*>("statusMessage");
  return label ? label->text() : QString();
}

}  // namespace

TEST(Wording, CountsAreSingularForOne) {
  EXPECT_EQ(counted(1, "iteration").toStdString(), "1 iteration");
  EXPECT_EQ(counted(0, "iteration").toStdString(), "0 iterations");
  EXPECT_EQ(counted(2, "patch", "patches").toStdString(), "2 patches");
  EXPECT_EQ(solveSummary("bounces", rt::SolverStatus::Success, 1, 0.5).toStdString(),
            "bounces: success after 1 bounce, residual 0.5");
  EXPECT_EQ(statusText("random-walk", rt::SolverStatus::NoConvergence).toStdString(), "noise level reached");
  EXPECT_EQ(statusText("jacobi", rt::SolverStatus::NoConvergence).toStdString(), "no convergence");
}

// The Cornell box, bounce by bounce: the reader types 1 into the bounces box and reads "1 bounce".
TEST(Wording, OneBounceIsOneBounceInTheStatusLine) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("cornell-box", 0)) << window->lastError().toStdString();
  QWidget* bounces = window->parameterPanel()->editor("bounces");
  ASSERT_NE(bounces, nullptr);
  test::typeInto(bounces, "1");
  ASSERT_EQ(window->result()->solverName, "bounces");
  EXPECT_TRUE(statusLine(*window).contains("after 1 bounce,")) << statusLine(*window).toStdString();
  EXPECT_FALSE(statusLine(*window).contains("1 bounces")) << statusLine(*window).toStdString();
  EXPECT_FALSE(statusLine(*window).contains("iterations")) << statusLine(*window).toStdString();
  test::typeInto(bounces, "3");
  EXPECT_TRUE(statusLine(*window).contains("after 3 bounces,")) << statusLine(*window).toStdString();
}

// The stochastic lesson: Right from its page on Jacobi with lines to the regular stochastic Jacobi solve,
// which stops on its ray budget. The status line says the noise level was reached, never "no convergence".
TEST(Wording, AStochasticSolveReachesItsNoiseLevel) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("stochastic", 2)) << window->lastError().toStdString();
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  window->textView()->setFocus();
  QTest::keyClick(window.get(), Qt::Key_Right);
  ASSERT_EQ(window->currentStep(), 3);
  ASSERT_NE(window->result(), nullptr);
  const QString status = statusLine(*window);
  EXPECT_FALSE(status.contains("no convergence")) << status.toStdString();
  if (window->result()->status == rt::SolverStatus::NoConvergence) {
    EXPECT_TRUE(status.contains("noise level reached")) << status.toStdString();
  }
  EXPECT_TRUE(isStochasticSolver(window->result()->solverName)) << window->result()->solverName;
}

// The core names settings as the command line spells them; the app says which control to change.
TEST(Wording, MessagesNameTheAppsControlsNotCommandLineOptions) {
  EXPECT_EQ(inAppTerms("use a coarser mesh, e.g. --no-subdivide)").toStdString(),
            "use a coarser mesh, e.g. the Subdivision (N x N) control at 1)");
  EXPECT_EQ(inAppTerms("Use a coarser mesh, e.g. --max-edge 40 (about 10,000 elements)").toStdString(),
            "Use a coarser mesh, e.g. the Max edge control at 40 (about 10,000 elements)");
  EXPECT_EQ(inAppTerms("or --mesh adaptive").toStdString(), "or --mesh adaptive") << "not a control: kept";
}

TEST(Wording, ATooLargeLatexExportSaysWhatToDoInTheApp) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("cornell-box", 1));
  ASSERT_TRUE(window->waitUntilIdle());
  const QString path = QDir::temp().filePath("rt-wording-F.tex");
  ASSERT_FALSE(window->exportMatrixFile("F", path)) << "the step's F is too large for LaTeX";
  const std::string error = window->lastError().toStdString();
  EXPECT_NE(error.find("LaTeX"), std::string::npos) << error;
  EXPECT_EQ(error.find("--"), std::string::npos) << error;
  EXPECT_NE(error.find("Subdivision (N x N) control"), std::string::npos) << error;
}
