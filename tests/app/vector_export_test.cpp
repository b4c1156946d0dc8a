// Exports as good as the command line's: the step's 2D figures through File > Export this step's figures
// (its save dialog answered as a reader answers it) are vectors, paths and text with no raster inside; a
// LaTeX matrix is a document that compiles at the largest size the app writes.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <fstream>
#include <sstream>

#include "app/exports.h"
#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app_test_support.h"
#include "core/io/matrix_export.h"
#include "support/vector_chart_check.h"

using namespace rt::app;

namespace {

QString readAll(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

void expectVectorSvg(const QString& file, bool withText) {
  ASSERT_TRUE(file.endsWith(".svg")) << file.toStdString();
  const QString svg = readAll(file);
  ASSERT_FALSE(svg.isEmpty()) << file.toStdString();
  EXPECT_TRUE(svg.contains("<svg")) << file.toStdString();
  EXPECT_TRUE(svg.contains("<path") || svg.contains("<polygon") || svg.contains("<rect"))
      << file.toStdString() << ": no vector shapes";
  if (withText) {
    EXPECT_TRUE(svg.contains("<text")) << file.toStdString() << ": no text";
  }
  EXPECT_FALSE(svg.contains("<image")) << file.toStdString() << ": an embedded raster";
  EXPECT_FALSE(svg.contains("data:image/png")) << file.toStdString();
}

}  // namespace

// The matrix step through the menu's shortcut and its save dialog: the proposed name, then a vector SVG.
TEST(VectorExport, TheStepsFiguresAreVectorSvgWithASuggestedName) {
  RT_REQUIRE_DISPLAY();
  QTemporaryDir dir;
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("radiosity-matrix", 0)) << window->lastError().toStdString();
  QString suggested;
  test::answerSaveDialog(dir.filePath("matrix.svg"), &suggested);
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  QTest::keyClick(window.get(), Qt::Key_E, Qt::ControlModifier | Qt::ShiftModifier);
  EXPECT_EQ(suggested.toStdString(), "radiosity-matrix-1-figures.svg");
  ASSERT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
  ASSERT_EQ(window->lastExportedFiles().size(), 1);
  expectVectorSvg(window->lastExportedFiles().front(), /*withText=*/true);
}

// The shooting lesson, step 2, its convergence chart exported as PDF and SVG: a line that other programs
// draw as a line (not the plot area filled with its colour), with its text in place.
TEST(VectorExport, TheStepsChartIsReadableInPdfAndSvg) {
  RT_REQUIRE_DISPLAY();
  RT_REQUIRE_VECTOR_RENDERERS();
  QTemporaryDir dir;
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("shooting", 1)) << window->lastError().toStdString();
  for (const QString format : {"pdf", "svg"}) {
    ASSERT_TRUE(window->exportStepFigures(dir.path(), format)) << window->lastError().toStdString();
    ASSERT_EQ(window->lastExportedFiles().size(), 1);
    rt::test::expectReadableChart(window->lastExportedFiles().front().toStdString(),
                                  {"iteration", "relative", "residual"}, 1);
  }
}

// The same step through Ctrl+Shift+E, a name typed into the save dialog and Enter: the file has the typed
// name, its extension the format, not the step's figure name.
TEST(VectorExport, TheStepsFigureTakesTheTypedName) {
  RT_REQUIRE_DISPLAY();
  QTemporaryDir dir;
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("shooting", 1)) << window->lastError().toStdString();
  for (const QString name : {"my-convergence.pdf", "my-convergence.svg"}) {
    test::answerSaveDialog(dir.filePath(name), nullptr);
    window->activateWindow();
    QApplication::setActiveWindow(window.get());
    QTest::keyClick(window.get(), Qt::Key_E, Qt::ControlModifier | Qt::ShiftModifier);
    ASSERT_TRUE(window->lastError().isEmpty()) << window->lastError().toStdString();
    EXPECT_EQ(window->lastExportedFiles(), QStringList{dir.filePath(name)});
    EXPECT_TRUE(QFile::exists(dir.filePath(name))) << name.toStdString();
  }
  EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files),
            (QStringList{"my-convergence.pdf", "my-convergence.svg"}));
}

// Every 2D kind the app draws: a chart (the convergence of Jacobi), the hemicube's faces; a 3D view (the
// row of F on the scene) has no vector form and is not among them.
TEST(VectorExport, ChartsAndHemicubeFacesAreVectors) {
  RT_REQUIRE_DISPLAY();
  QTemporaryDir dir;
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("gathering", 0)) << window->lastError().toStdString();
  ASSERT_TRUE(window->exportStepFigures(dir.filePath("chart"), "svg")) << window->lastError().toStdString();
  ASSERT_EQ(window->lastExportedFiles().size(), 1);
  expectVectorSvg(window->lastExportedFiles().front(), /*withText=*/true);
  ASSERT_TRUE(window->openLesson("hemicube", 1)) << window->lastError().toStdString();
  ASSERT_TRUE(window->exportStepFigures(dir.filePath("hemicube"), "svg"))
      << window->lastError().toStdString();
  ASSERT_EQ(window->lastExportedFiles().size(), 2);
  expectVectorSvg(window->lastExportedFiles().front(), /*withText=*/false);  // the faces: cells, no labels
}

TEST(VectorExport, TheConvergenceChartIsAVectorPdfToo) {
  RT_REQUIRE_DISPLAY();
  QTemporaryDir dir;
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("gathering", 0)) << window->lastError().toStdString();
  ASSERT_TRUE(window->exportStepFigures(dir.path(), "pdf")) << window->lastError().toStdString();
  ASSERT_EQ(window->lastExportedFiles().size(), 1);
  const QByteArray pdf = [&] {
    QFile f(window->lastExportedFiles().front());
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
  }();
  EXPECT_TRUE(pdf.startsWith("%PDF"));
  EXPECT_FALSE(pdf.contains("/Subtype /Image")) << "an embedded raster";
}

// The matrix K of a small scene through File > Export matrix K, saved as .tex: a document with the preamble a
// wide bmatrix needs and no number TeX cannot read.
TEST(VectorExport, ALatexMatrixCompilesAtTheLargestSize) {
  QTemporaryDir dir;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m(rt::kMaxLatexSize,
                                                                           rt::kMaxLatexSize);
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j)
      m(i, j) = (i == j ? 1.0 : -4.28698e-06 * (1 + i + j)) * (j % 3 ? 1 : 1e7);
  const std::string fragmentPath = dir.filePath("fragment.tex").toStdString();
  rt::writeMatrix(m, fragmentPath);
  std::ifstream in(fragmentPath);
  std::stringstream fragment;
  fragment << in.rdbuf();
  const std::string tex = latexDocument(fragment.str(), m.cols());
  EXPECT_NE(tex.find("\\documentclass"), std::string::npos);
  EXPECT_NE(tex.find("\\usepackage{amsmath}"), std::string::npos);
  EXPECT_NE(tex.find("\\setcounter{MaxMatrixCols}{20}"), std::string::npos) << tex.substr(0, 400);
  EXPECT_NE(tex.find("\\times 10^{-6}"), std::string::npos);
  EXPECT_EQ(tex.find("e-0"), std::string::npos) << "a number in e notation";
  EXPECT_EQ(tex.find("e+0"), std::string::npos) << "a number in e notation";
  const QString texPath = dir.filePath("K.tex");
  std::ofstream(texPath.toStdString()) << tex;
  const QString pdflatex = QStandardPaths::findExecutable("pdflatex");
  if (pdflatex.isEmpty()) GTEST_SKIP() << "no pdflatex: the preamble was checked, the document not compiled";
  QProcess latex;
  latex.setWorkingDirectory(dir.path());
  latex.start(pdflatex, {"-interaction=nonstopmode", "-halt-on-error", "K.tex"});
  ASSERT_TRUE(latex.waitForFinished(120000));
  EXPECT_EQ(latex.exitCode(), 0) << latex.readAllStandardOutput().toStdString();
  EXPECT_TRUE(QFile::exists(dir.filePath("K.pdf")));
}

TEST(VectorExport, TheAppsLatexExportIsADocument) {
  RT_REQUIRE_DISPLAY();
  QTemporaryDir dir;
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(QString::fromStdString(RT_SOURCE_DIR "/scenes/parallel-squares.json")));
  test::typeInto(window->parameterPanel()->editor("subdivide"), "2");  // 8 elements: small enough for TeX
  QString suggested;
  const QString path = dir.filePath("F.tex");
  test::answerSaveDialog(path, &suggested);
  QAction* action = test::menuAction(*window, "File", "Export form factors F...");
  ASSERT_NE(action, nullptr);
  action->trigger();
  EXPECT_EQ(suggested.toStdString(), "parallel-squares-F.csv");
  const QString tex = readAll(path);
  ASSERT_FALSE(tex.isEmpty()) << window->lastError().toStdString();
  EXPECT_TRUE(tex.contains("\\setcounter{MaxMatrixCols}"));
  EXPECT_TRUE(tex.contains("\\begin{bmatrix}"));
  EXPECT_TRUE(tex.contains("\\end{document}"));
}
