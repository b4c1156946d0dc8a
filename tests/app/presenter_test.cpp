// Presenter mode at 1920 x 1080, for the back of a lecture hall: body text of 28 px at least, the zoom keys,
// a step of text over the whole screen, the step's figure large in the main pane, and every font (the chart's
// too) given back on leaving. Screenshots of a text, an equation, a figure and a chart step are written to
// build/.../tests/screenshots for a reader to look at.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QMap>
#include <QTest>

#include "app/figures_pane.h"
#include "app/lesson_session.h"
#include "app/residual_chart.h"
#include "app/screenshot.h"
#include "app_test_support.h"

using namespace rt::app;

namespace {

int bodyPixels(MainWindow& window) {
  return window.textView()->textPixelSize();
}

// The smallest size of the step's typeset equations on the page (KaTeX's nodes), or 0 without any.
int smallestEquationPixels(MainWindow& window) {
  return static_cast<int>(window.textView()->mathsState().smallestEquationPixels);
}

void shoot(MainWindow& window, const char* name) {
  QTest::qWait(100);
  QDir().mkpath(RT_BINARY_DIR "/tests/screenshots");
  const QImage image = grabWindow(window);
  image.save(QString(RT_BINARY_DIR "/tests/screenshots/presenter-%1.png").arg(name));
  EXPECT_GT(pixelStatistics(image).distinctColours, 8) << name;
}

QMap<QWidget*, QString> fontsOf(QWidget& window) {
  QMap<QWidget*, QString> fonts;
  for (QWidget* w : window.findChildren<QWidget*>()) fonts[w] = w->font().toString();
  return fonts;
}

void press(MainWindow& window, int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
  QTest::keyClick(&window, static_cast<Qt::Key>(key), modifiers);
}

}  // namespace

TEST(Presenter, LargeTextZoomAndTheWholeScreenForText) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->resize(1920, 1080);
  ASSERT_TRUE(window->openLesson("hemicube", 0));  // a step of text
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  const int normal = bodyPixels(*window);
  press(*window, Qt::Key_F11);
  ASSERT_TRUE(window->presenterMode());
  QTest::qWait(200);
  EXPECT_GE(bodyPixels(*window), 28);
  EXPECT_GT(bodyPixels(*window), normal);
  EXPECT_GE(window->textView()->mathsState().bodyPixels, 28) << "the page's text follows the widget's font";
  // The step's equations ("delta F_top = ...") are as large as the text.
  ASSERT_GT(smallestEquationPixels(*window), 0) << "the step has no equation to check";
  EXPECT_GE(smallestEquationPixels(*window), bodyPixels(*window));
  // The text of a text step covers the screen, not a column of it.
  EXPECT_GT(window->textView()->width(), window->width() * 8 / 10);
  shoot(*window, "text");
  const int before = bodyPixels(*window);
  press(*window, Qt::Key_Plus, Qt::ControlModifier);
  EXPECT_GT(bodyPixels(*window), before);
  press(*window, Qt::Key_Minus, Qt::ControlModifier);
  press(*window, Qt::Key_Minus, Qt::ControlModifier);
  EXPECT_LT(bodyPixels(*window), before);
  press(*window, Qt::Key_Escape);
  EXPECT_FALSE(window->presenterMode());
  EXPECT_EQ(bodyPixels(*window), normal);
}

TEST(Presenter, EquationFigureAndChartStepsAndEveryFontBack) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->resize(1920, 1080);
  ASSERT_TRUE(window->openLesson("gathering", 0));
  QTest::qWait(100);
  const QMap<QWidget*, QString> fonts = fontsOf(*window);
  const QString chartFont = window->residualChart()->labelsFont().toString();
  const QString axisTitleFont = window->residualChart()->axisTitleFont().toString();
  ASSERT_TRUE(window->residualChart()->axisTitleFont().bold()) << "Qt Charts sets axis titles in bold";
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  press(*window, Qt::Key_F11);
  ASSERT_TRUE(window->presenterMode());
  EXPECT_NE(window->residualChart()->labelsFont().toString(), chartFont);
  EXPECT_TRUE(window->residualChart()->axisTitleFont().bold()) << "larger, and still bold";
  shoot(*window, "chart");
  ASSERT_TRUE(window->openLesson("rendering-equation", 1));
  shoot(*window, "equation");
  ASSERT_TRUE(window->openLesson("hemicube", 1));
  press(*window, Qt::Key_F);  // the step's figure in the main pane
  EXPECT_TRUE(window->largeFigure());
  QTest::qWait(100);
  EXPECT_GT(window->figuresPane()->width(), window->width() / 2);
  shoot(*window, "figure");
  press(*window, Qt::Key_Escape);
  ASSERT_FALSE(window->presenterMode());
  EXPECT_FALSE(window->largeFigure());
  ASSERT_TRUE(window->openLesson("gathering", 0));
  QApplication::processEvents();
  EXPECT_EQ(window->residualChart()->labelsFont().toString(), chartFont);
  EXPECT_EQ(window->residualChart()->axisTitleFont().toString(), axisTitleFont);
  EXPECT_TRUE(window->residualChart()->axisTitleFont().bold()) << "the axis titles are bold again";
  int differ = 0;
  for (auto it = fonts.begin(); it != fonts.end(); ++it) {
    if (!window->findChildren<QWidget*>().contains(it.key())) continue;  // a widget of another step
    if (it.key()->font().toString() != it.value()) {
      ++differ;
      ADD_FAILURE() << it.key()->metaObject()->className() << " " << it.key()->objectName().toStdString()
                    << ": " << it.value().toStdString() << " -> "
                    << it.key()->font().toString().toStdString();
    }
  }
  EXPECT_EQ(differ, 0);
}
