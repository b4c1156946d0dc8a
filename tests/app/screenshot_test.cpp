// What the reader sees: the 3D view inside the window holds a real image (not the black or empty frame a
// broken GL hosting gives), for the built-in Cornell box and for key lesson steps; and `--screenshot` writes
// such an image.
#include <gtest/gtest.h>

#include <QImage>
#include <QLabel>
#include <QTabBar>
#include <QTabWidget>
#include <QTest>

#include "app/figures_pane.h"
#include "app/residual_chart.h"
#include "app/scene_view.h"
#include "app/screenshot.h"
#include "app_test_support.h"
#include "support/test_paths.h"

using namespace rt::app;

namespace {

void expectRealImage(MainWindow& window, const std::string& what) {
  const QImage image = grabWindow(window);
  const QRect area = test::areaOf(&window, window.primaryView());
  const PixelStatistics stats = pixelStatistics(image, area);
  EXPECT_GT(stats.meanLuminance, 25) << what;
  EXPECT_GT(stats.stdDevLuminance, 8) << what;
  EXPECT_GT(stats.distinctColours, 30) << what;
  EXPECT_GT(stats.nonBlackFraction, 0.5) << what;
}

}  // namespace

TEST(Screenshot, PixelStatisticsTellBlackFromAnImage) {
  QImage black(64, 64, QImage::Format_RGB32);
  black.fill(Qt::black);
  const PixelStatistics none = pixelStatistics(black);
  EXPECT_EQ(none.meanLuminance, 0);
  EXPECT_EQ(none.distinctColours, 1);
  EXPECT_EQ(none.nonBlackFraction, 0);
  QImage ramp(256, 1, QImage::Format_RGB32);
  for (int x = 0; x < 256; ++x) ramp.setPixel(x, 0, qRgb(x, x, x));
  const PixelStatistics some = pixelStatistics(ramp);
  EXPECT_NEAR(some.meanLuminance, 127.5, 0.01);
  EXPECT_EQ(some.distinctColours, 256);
}

TEST(Screenshot, BuiltInCornellBoxShowsInTheView) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString())) << window->lastError().toStdString();
  expectRealImage(*window, "built-in Cornell box");
}

TEST(Screenshot, KeyLessonStepsShowInTheView) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  for (const auto& [lesson, step] :
       std::vector<std::pair<QString, int>>{{"cornell-box", 3}, {"gathering", 0}}) {
    if (!window->openLesson(lesson, step)) {
      ADD_FAILURE() << window->lastError().toStdString();
      continue;
    }
    expectRealImage(*window, lesson.toStdString() + " step " + std::to_string(step + 1));
  }
}

// A benchmark step solves nothing: the view shows the materials under a headlight (with the radiosity
// colouring of an ambient estimate, the box's white walls and floor were one flat colour); its charts fit the
// pane.
TEST(Screenshot, AStepWithoutASolutionShowsTheShadedMaterials) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->resize(1400, 900);
  ASSERT_TRUE(window->openLesson("runtime-error-lab", 0)) << window->lastError().toStdString();
  EXPECT_TRUE(window->primaryView()->materialView());
  EXPECT_EQ(window->primaryView()->viewOptions().colouring, rt::viz::SceneColouring::Reflectance);
  expectRealImage(*window, "runtime-error-lab step 1");
  const auto figures = window->figuresPane()->findChildren<QLabel*>("figure");
  ASSERT_FALSE(figures.empty());
  for (const QLabel* figure : figures)
    EXPECT_LE(figure->pixmap().width(), window->figuresPane()->viewport()->width());
  // No solver ran: the convergence chart says so instead of showing empty axes.
  EXPECT_FALSE(window->residualChart()->chart()->title().isEmpty());
  ASSERT_TRUE(window->openLesson("cornell-box", 3)) << window->lastError().toStdString();
  EXPECT_FALSE(window->primaryView()->materialView());
  EXPECT_EQ(window->primaryView()->viewOptions().colouring, rt::viz::SceneColouring::Radiosity);
}

// The shooting lesson, step 2, the Step figures tab clicked open in the pane under the 3D view: the
// convergence chart and its caption are seen whole, not cut at the pane's bottom.
TEST(Screenshot, TheStepFiguresTabShowsTheFigureWhole) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->resize(1600, 1000);
  window->show();
  ASSERT_TRUE(window->openLesson("shooting", 1)) << window->lastError().toStdString();
  FiguresPane* pane = window->figuresPane();
  QTabWidget* tabs = nullptr;
  for (QWidget* w = pane->parentWidget(); w && !tabs; w = w->parentWidget())
    tabs = qobject_cast<QTabWidget*>(w);
  ASSERT_NE(tabs, nullptr);
  QTest::mouseClick(tabs->tabBar(), Qt::LeftButton, Qt::NoModifier,
                    tabs->tabBar()->tabRect(tabs->indexOf(pane)).center());
  ASSERT_EQ(tabs->currentWidget(), pane);
  QApplication::processEvents();
  const auto figures = pane->findChildren<QLabel*>("figure");
  ASSERT_EQ(figures.size(), 1);
  const QLabel* figure = figures.front();
  const QRect shown(figure->mapTo(pane->viewport(), QPoint(0, 0)), figure->pixmap().size());
  EXPECT_TRUE(pane->viewport()->rect().contains(shown))
      << "the figure at " << shown.x() << "," << shown.y() << " " << shown.width() << "x" << shown.height()
      << " in a pane of " << pane->viewport()->width() << "x" << pane->viewport()->height();
}

// An exact step's view shows the radiosity solved with its first approximate method's form factors (the
// hemicube's, whose eye point on the receiver sees only the occluder: a black receiver); the caption says so.
TEST(Screenshot, AnExactStepSaysWhoseRadiosityItShows) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  if (!window->openLesson("exact-reference", 1)) GTEST_SKIP() << window->lastError().toStdString();
  EXPECT_EQ(window->primaryView()->caption().toStdString(), "Radiosity with hemicube form factors");
  ASSERT_NE(window->result(), nullptr);
  EXPECT_EQ(window->result()->formFactorMethod, "hemicube");
}

// A step that compares solvers (direct against the two stochastic Jacobis) replays one it compares, which
// its text describes, not the default solver it never names.
TEST(Screenshot, ACompareStepReplaysTheSolverItCompares) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("stochastic", 5)) << window->lastError().toStdString();
  ASSERT_NE(window->result(), nullptr);
  const std::string solver = window->result()->solverName;
  EXPECT_TRUE(solver == "local-lines-regular" || solver == "local-lines") << solver;
  EXPECT_NE(window->primaryView()->caption().toStdString().find(solver), std::string::npos);
}

// The 3D view of key steps against baselines (Mesa's software renderer draws the same pixels run after run;
// the threshold absorbs small changes of shading).
TEST(Screenshot, KeyLessonStepsMatchTheirBaselines) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->resize(1400, 900);
  for (const auto& [lesson, step] : std::vector<std::pair<QString, int>>{
           {"cornell-box", 1}, {"cornell-box", 3}, {"gathering", 0}, {"hemicube", 1}}) {
    ASSERT_TRUE(window->openLesson(lesson, step)) << window->lastError().toStdString();
    const QImage view = grabWindow(*window).copy(test::areaOf(window.get(), window->primaryView()));
    const std::string name = "app_" + lesson.toStdString() + "_" + std::to_string(step + 1) + ".png";
    view.save(QString::fromStdString(rt::test::scratchDir("app-baseline-" + name) + "/" + name));
    const double difference = test::differenceFromBaseline(view, name);
    ASSERT_GE(difference, 0.0) << "no baseline tests/baselines/" << name << " of size " << view.width() << "x"
                               << view.height();
    EXPECT_LT(difference, 4.0) << name;
  }
}

// Debian's VTK Qt module is built with Qt 5: loading it next to Qt 6 crashes, so the app must never link it.
TEST(Screenshot, TheAppLinksQt6AndNoQt5) {
  std::string output;
  ASSERT_EQ(rt::test::runCommand("ldd " + rt::test::binaryPath("bin/radiosity-textbook"), &output), 0)
      << output;
  EXPECT_NE(output.find("libQt6Widgets"), std::string::npos) << output;
  EXPECT_NE(output.find("libQt6OpenGLWidgets"), std::string::npos) << output;
  EXPECT_EQ(output.find("Qt5"), std::string::npos) << output;
  EXPECT_EQ(output.find("vtkGUISupportQt"), std::string::npos) << output;
}

TEST(Screenshot, CommandLineWritesAWindowImage) {
  RT_REQUIRE_DISPLAY();
  const std::string dir = rt::test::scratchDir("app-screenshot");
  const std::string png = dir + "/cornell.png";
  const std::string app = rt::test::binaryPath("bin/radiosity-textbook");
  std::string output;
  const int code =
      rt::test::runCommand("cd " + rt::test::sourcePath("") + " && " + app +
                               " --lesson cornell-box --step 4 --size 1200x800 --screenshot " + png,
                           &output);
  ASSERT_EQ(code, 0) << output;
  // Neither the 3D view's nor the text pane's set-up talks on stderr: no fall-back from the core profile,
  // no transient failure of WebEngine's GPU process (the text pane needs no GPU).
  for (const char* noise : {"Core Profile", "GpuControl", "kTransientFailure"})
    EXPECT_EQ(output.find(noise), std::string::npos) << noise << " in:\n" << output;
  QImage image(QString::fromStdString(png));
  ASSERT_FALSE(image.isNull());
  EXPECT_EQ(image.size(), QSize(1200, 800));
  // The centre right of the window is the 3D view.
  const PixelStatistics stats = pixelStatistics(image, QRect(700, 150, 300, 300));
  EXPECT_GT(stats.meanLuminance, 25);
  EXPECT_GT(stats.distinctColours, 30);
}

TEST(Screenshot, CommandLineNamesAnUnknownLesson) {
  RT_REQUIRE_DISPLAY();
  const std::string app = rt::test::binaryPath("bin/radiosity-textbook");
  std::string output;
  const int code =
      rt::test::runCommand(app + " --lesson no-such-lesson --screenshot /tmp/never.png", &output);
  EXPECT_NE(code, 0);
  EXPECT_NE(output.find("no-such-lesson"), std::string::npos) << output;
}

TEST(Screenshot, CommandLineComparesMeshesSideBySide) {
  RT_REQUIRE_DISPLAY();
  const std::string png = rt::test::scratchDir("app-screenshot-compare") + "/compare.png";
  const std::string app = rt::test::binaryPath("bin/radiosity-textbook");
  std::string output;
  const int code = rt::test::runCommand(
      app + " --lesson cornell-box --step 4 --compare-mesh finer --size 1400x800" + " --screenshot " + png,
      &output);
  ASSERT_EQ(code, 0) << output;
  QImage image(QString::fromStdString(png));
  ASSERT_FALSE(image.isNull());
  // Both halves of the view area show a lit room.
  for (const QRect& pane : {QRect(600, 150, 160, 250), QRect(1000, 150, 160, 250)}) {
    const PixelStatistics stats = pixelStatistics(image, pane);
    EXPECT_GT(stats.meanLuminance, 25) << pane.x();
    EXPECT_GT(stats.distinctColours, 30) << pane.x();
  }
}

TEST(Screenshot, CommandLineNamesAnUnknownCompareMethod) {
  RT_REQUIRE_DISPLAY();
  const std::string app = rt::test::binaryPath("bin/radiosity-textbook");
  std::string output;
  const int code = rt::test::runCommand(
      app + " --lesson cornell-box --compare-method no-such-method --screenshot /tmp/never.png", &output);
  EXPECT_NE(code, 0);
  EXPECT_NE(output.find("--compare-method"), std::string::npos) << output;
  EXPECT_NE(output.find("hemicube"), std::string::npos) << output;
}
