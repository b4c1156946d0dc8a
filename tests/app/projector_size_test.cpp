// The app on a 1024 x 768 projector: the window can be made that small on every lesson's steps, with the
// parameter panel reachable and the chart's tick labels whole.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDebug>
#include <QDockWidget>
#include <QFontMetrics>
#include <QFontMetricsF>
#include <QScrollArea>
#include <QSplitter>
#include <QTest>
#include <cmath>

#include "app/residual_chart.h"
#include "app_test_support.h"

using namespace rt::app;

namespace {

// Prints the widgets whose minimum width is widest: where a too-wide window comes from.
void reportWidest(QWidget* root) {
  std::vector<std::pair<int, QWidget*>> widths;
  for (QWidget* w : root->findChildren<QWidget*>())
    if (w->isVisible()) widths.emplace_back(w->minimumSizeHint().width(), w);
  std::sort(widths.begin(), widths.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t k = 0; k < std::min<std::size_t>(25, widths.size()); ++k)
    qInfo() << widths[k].first << widths[k].second->metaObject()->className()
            << widths[k].second->objectName() << widths[k].second->parentWidget()->metaObject()->className();
}

}  // namespace

TEST(ProjectorSize, TheWindowFitsA1024By768Screen) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  for (const char* lesson : {"shooting", "cornell-box", "two-solutions", "hemicube"}) {
    ASSERT_TRUE(window->openLesson(lesson, 1));
    ASSERT_TRUE(window->waitUntilIdle());
    window->resize(1024, 700);
    QApplication::processEvents();
    if (window->minimumSizeHint().width() > 1024) reportWidest(window.get());
    EXPECT_LE(window->minimumSizeHint().width(), 1024) << lesson;
    EXPECT_LE(window->width(), 1024) << lesson;
    // The parameters are all in sight: the panel fits its dock's width.
    auto* dock = window->findChild<QDockWidget*>("parametersDock");
    ASSERT_NE(dock, nullptr);
    auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
    ASSERT_NE(scroll, nullptr);
    EXPECT_LE(scroll->widget()->minimumSizeHint().width(), scroll->viewport()->width())
        << lesson << ": the parameter panel is wider than its dock";
  }
}

TEST(ProjectorSize, ChartLabelsFitAShortWindow) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  ASSERT_TRUE(window->openLesson("gathering", 1));
  ASSERT_TRUE(window->waitUntilIdle());
  ResidualChart* chart = window->residualChart();
  ASSERT_NE(chart, nullptr);
  // Twelve decades of residual, as a long Jacobi run gives, in a window 600 px high.
  std::vector<double> residuals;
  for (int k = 0; k <= 24; ++k) residuals.push_back(std::pow(10.0, -0.5 * k));
  chart->setRuns({"Jacobi"}, {residuals});
  for (int height : {1000, 600}) {
    window->resize(1024, height);
    QApplication::processEvents();
    QApplication::processEvents();
    const double room = chart->chart()->plotArea().height();
    const double labelHeight = QFontMetricsF(chart->labelsFont()).height();
    EXPECT_GE(chart->residualLabels(), 2) << height;
    EXPECT_LE(chart->residualLabels() * labelHeight, room)
        << "labels of the residual axis at window height " << height
        << " would be elided: " << chart->residualLabels() << " labels in " << room << " px";
  }
}

// At 1024 x 768 the step's text keeps a readable width: the contents list folds away (beside it and the
// parameters the text was a column of about 150 px) and comes back from the View menu; the window made wide
// again shows the list again.
TEST(ProjectorSize, TheTextKeepsAReadableWidthAt1024) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  ASSERT_TRUE(window->openLesson("cornell-box", 1));
  ASSERT_TRUE(window->waitUntilIdle());
  auto* contents = window->findChild<QDockWidget*>("contentsDock");
  auto* text = window->findChild<QWidget*>("stepText");
  ASSERT_NE(contents, nullptr);
  ASSERT_NE(text, nullptr);
  EXPECT_TRUE(contents->isVisible());
  window->resize(1024, 768);
  QApplication::processEvents();
  QApplication::processEvents();
  if (text->width() < 320)
    qInfo() << "centre" << qobject_cast<QSplitter*>(window->centralWidget())->sizes()
            << window->findChild<QDockWidget*>("parametersDock")->width()
            << qobject_cast<QSplitter*>(window->centralWidget())->widget(1)->minimumSizeHint()
            << qobject_cast<QSplitter*>(window->centralWidget())->widget(0)->minimumSizeHint();
  // About 45 characters of the text's font a line: a readable column.
  const int readable = 45 * QFontMetrics(text->font()).averageCharWidth();
  EXPECT_GE(text->width(), readable) << "the text pane at 1024 px";
  EXPECT_GE(text->width(), 320);
  EXPECT_FALSE(contents->isVisible()) << "the contents list folded away";
  // View > Contents brings it back when the reader wants it.
  QAction* show = test::menuAction(*window, "View", "Contents");
  ASSERT_NE(show, nullptr);
  show->trigger();
  QApplication::processEvents();
  EXPECT_TRUE(contents->isVisible());
  show->trigger();
  QApplication::processEvents();
  window->resize(1600, 1000);
  QApplication::processEvents();
  QApplication::processEvents();
  EXPECT_TRUE(contents->isVisible()) << "a wide window shows the list again";
}
