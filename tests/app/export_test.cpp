// Exports: the view exported from the app is the image `radiosity solve --image` renders for the same scene
// and settings (the same viz exporter), matrices are written through rt::writeMatrix, and a whole lesson's
// figures are written at once.
#include <gtest/gtest.h>

#include <QFile>
#include <QImage>
#include <filesystem>
#include <fstream>

#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app_test_support.h"
#include "support/test_paths.h"

using namespace rt::app;

TEST(Export, ViewIsTheImageTheCommandLineRenders) {
  RT_REQUIRE_DISPLAY();
  const std::string scene = rt::test::sourcePath("scenes/cornell-box.json");
  if (!std::filesystem::exists(scene)) GTEST_SKIP() << "no " << scene;
  const std::string dir = rt::test::scratchDir("app-export-view");
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString::fromStdString(scene))) << window->lastError().toStdString();
  rt::lesson::StepParameters p = window->parameterPanel()->parameters();
  p.method = "analytic";
  p.solver = "direct";
  p.subdivide = 2;
  window->applyParameters(p);
  ASSERT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
  const std::string fromApp = dir + "/app.png";
  ASSERT_TRUE(window->exportView(QString::fromStdString(fromApp), QSize(480, 360)))
      << window->lastError().toStdString();

  const std::string fromCli = dir + "/cli.png";
  std::string output;
  const int code = rt::test::runCommand(rt::test::cliPath() + " solve " + scene +
                                            " --formfactors analytic --method direct --subdivide 2 --image " +
                                            fromCli + " --width 480 --height 360",
                                        &output);
  ASSERT_EQ(code, 0) << output;
  const QImage a(QString::fromStdString(fromApp)), b(QString::fromStdString(fromCli));
  ASSERT_FALSE(a.isNull());
  ASSERT_FALSE(b.isNull());
  ASSERT_EQ(a.size(), b.size());
  // Same pixels (the same renderer on the same B from the same camera).
  long different = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) different += a.pixel(x, y) != b.pixel(x, y);
  EXPECT_EQ(different, 0) << "pixels that differ between the app's and the CLI's image";
}

TEST(Export, MatricesAndVectorsInEveryFormat) {
  RT_REQUIRE_DISPLAY();
  const std::string dir = rt::test::scratchDir("app-export-matrix");
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString()));
  rt::lesson::StepParameters p = window->parameterPanel()->parameters();
  p.subdivide = 1;
  window->applyParameters(p);
  const PipelineResult* r = window->result();
  ASSERT_NE(r, nullptr);
  ASSERT_NE(r->F, nullptr);
  const auto n = r->F->rows();
  for (const char* ext : {"csv", "mtx", "npy", "tex"}) {
    const QString path = QString::fromStdString(dir) + "/F." + ext;
    if (QString(ext) == "tex" && n > 20) {
      EXPECT_FALSE(window->exportMatrixFile("F", path));  // LaTeX only for small matrices: a clear error
      EXPECT_FALSE(window->lastError().isEmpty());
      continue;
    }
    EXPECT_TRUE(window->exportMatrixFile("F", path)) << window->lastError().toStdString();
    EXPECT_GT(QFile(path).size(), 0) << ext;
  }
  // The CSV holds F row by row with enough digits to round-trip.
  ASSERT_TRUE(window->exportMatrixFile("F", QString::fromStdString(dir) + "/F.csv"));
  std::ifstream csv(dir + "/F.csv");
  std::string line;
  long rows = 0;
  while (std::getline(csv, line))
    if (!line.empty() && line[0] != '#') ++rows;
  EXPECT_GE(rows, n);
  EXPECT_TRUE(window->exportMatrixFile("B", QString::fromStdString(dir) + "/B.npy"));
  EXPECT_TRUE(window->exportMatrixFile("K", QString::fromStdString(dir) + "/K.mtx"));
}

TEST(Export, AllFiguresOfALesson) {
  RT_REQUIRE_DISPLAY();
  const std::string dir = rt::test::scratchDir("app-export-lesson");
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("cornell-box", 0)) << window->lastError().toStdString();
  ASSERT_TRUE(window->exportAllFigures(QString::fromStdString(dir))) << window->lastError().toStdString();
  int pngs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    pngs += entry.path().extension() == ".png";
  // One file per view of every step that names a figure, as `radiosity lesson render` writes them.
  const auto& lesson = window->library()->lessons()[window->currentLesson()];
  int expected = 0;
  for (const auto& step : lesson.steps) expected += static_cast<int>(step.figureFiles().size());
  EXPECT_EQ(pngs, expected);
  EXPECT_TRUE(std::filesystem::exists(dir + "/bounce-0.png"));
}
