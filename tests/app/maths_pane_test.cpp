// The step's text pane typesets its maths with KaTeX: the page reports KaTeX's nodes for every formula and no
// error, at normal size and in presenter mode, where the equations grow with the text. Screenshots of both
// are written to build/.../tests/screenshots for a reader to look at.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QTest>
#include <utility>
#include <vector>

#include "app/lesson_text_view.h"
#include "app/screenshot.h"
#include "app_test_support.h"
#include "lesson/lesson_references.h"
#include "support/test_paths.h"

using namespace rt::app;

namespace {

void shoot(MainWindow& window, const char* name) {
  QDir().mkpath(RT_BINARY_DIR "/tests/screenshots");
  const QImage image = grabWindow(window);
  image.save(QString(RT_BINARY_DIR "/tests/screenshots/maths-%1.png").arg(name));
  // The text pane shows dark text on light (or light on dark): more than one colour, not one flat area.
  const QRect pane = test::areaOf(&window, window.textView());
  EXPECT_GT(pixelStatistics(image, pane).distinctColours, 8) << name;
}

}  // namespace

TEST(MathsPane, TheLessonPaneShowsTypesetMathsWithoutErrors) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->resize(1600, 1000);
  window->show();
  ASSERT_TRUE(window->openLesson("rendering-equation", 2));  // the radiosity equation, displayed and numbered
  const LessonTextView::MathsState state = window->textView()->mathsState();
  ASSERT_TRUE(state.ready) << "the page was not typeset in time";
  EXPECT_GE(state.formulas, 5);
  EXPECT_EQ(state.katexNodes, state.formulas) << "every formula set by KaTeX";
  EXPECT_TRUE(state.errors.isEmpty()) << state.errors.join("; ").toStdString();
  const int chapter = rt::lesson::lessonNumbers(rt::test::sourcePath("lessons")).at("rendering-equation");
  EXPECT_TRUE(window->textView()->toPlainText().contains(QString("\\tag{%1.3}").arg(chapter)))
      << "numbered by the lesson";
  shoot(*window, "normal");
}

TEST(MathsPane, ListingsAndCitationsShowInThePane) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->resize(1600, 1000);
  window->show();
  ASSERT_TRUE(window->openLesson("shooting", 2));  // the ambient term: a citation and the chapter's listing 1
  const QString listing = QString("Algorithm %1.1")
                              .arg(rt::lesson::lessonNumbers(rt::test::sourcePath("lessons")).at("shooting"));
  const LessonTextView::MathsState state = window->textView()->mathsState();
  ASSERT_TRUE(state.ready) << "the page was not typeset in time";
  EXPECT_TRUE(state.errors.isEmpty()) << state.errors.join("; ").toStdString();
  EXPECT_EQ(state.katexNodes, state.formulas) << "the listing's maths set by KaTeX too";
  const QString text = window->textView()->toPlainText();
  EXPECT_TRUE(
      text.contains("<figure class=\"algorithm\" id=\"alg-shooting\"><figcaption><b>" + listing + "</b>"));
  EXPECT_TRUE(text.contains("[" + listing + "](#alg-shooting)"));
  // A citation links to the works listed under the step, its full entry on hover.
  EXPECT_TRUE(text.contains("[Cohen et al. 1988](#ref-cohen1988 \"Cohen, Michael F., Shenchang Eric Chen"))
      << text.toStdString();
  EXPECT_TRUE(text.contains("<p class=\"reference\" id=\"ref-cohen1988\">"));
  shoot(*window, "listing");
}

TEST(MathsPane, EveryLessonsMathsTypesetsInThePane) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->show();
  for (const char* lesson :
       {"form-factor", "hemicube", "radiosity-matrix", "gathering", "patches-to-pixels"}) {
    ASSERT_TRUE(window->openLesson(lesson, 0)) << lesson;
    const auto state = window->textView()->mathsState();
    ASSERT_TRUE(state.ready) << lesson;
    EXPECT_TRUE(state.errors.isEmpty()) << lesson << ": " << state.errors.join("; ").toStdString();
    EXPECT_EQ(state.katexNodes, state.formulas) << lesson;
  }
}

// At the default window size and at a projector's 1024 pixels, no equation number sits on its equation (the
// pages below are those where numbers did): a number that does not fit beside its equation goes under it.
TEST(MathsPane, EquationNumbersKeepClearOfTheirEquations) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->show();
  for (const QSize size : {QSize(1600, 1000), QSize(1024, 700)}) {
    window->resize(size);
    for (const auto& [lesson, step] : std::vector<std::pair<const char*, int>>{{"cornell-box", 0},
                                                                               {"gathering", 1},
                                                                               {"gathering", 2},
                                                                               {"form-factor", 1},
                                                                               {"radiosity-matrix", 1},
                                                                               {"rendering-equation", 1},
                                                                               {"measuring-light", 3},
                                                                               {"shooting", 2}}) {
      ASSERT_TRUE(window->openLesson(lesson, step)) << lesson;
      const auto state = window->textView()->mathsState();
      ASSERT_TRUE(state.ready) << lesson;
      EXPECT_EQ(state.numbersOverEquations, 0) << lesson << " step " << step << " at " << size.width();
    }
  }
}

TEST(MathsPane, PresenterModeScalesTheEquationsWithTheText) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->resize(1920, 1080);
  window->show();
  ASSERT_TRUE(window->openLesson("rendering-equation", 2));
  const auto normal = window->textView()->mathsState();
  ASSERT_GT(normal.smallestEquationPixels, 0);
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  QTest::keyClick(window.get(), Qt::Key_F11);
  ASSERT_TRUE(window->presenterMode());
  QTest::qWait(200);
  const auto presenter = window->textView()->mathsState();
  EXPECT_GE(presenter.bodyPixels, 28);
  EXPECT_GT(presenter.smallestEquationPixels, normal.smallestEquationPixels * 1.5);
  EXPECT_GE(presenter.smallestEquationPixels, presenter.bodyPixels) << "KaTeX sets maths at 1.21 em";
  EXPECT_TRUE(presenter.errors.isEmpty());
  shoot(*window, "presenter");
  QTest::keyClick(window.get(), Qt::Key_Escape);
  EXPECT_FALSE(window->presenterMode());
}

TEST(MathsPane, AFormulaThatDoesNotTypesetIsReportedNotHidden) {
  RT_REQUIRE_DISPLAY();
  LessonTextView view;
  view.resize(600, 400);
  view.show();
  view.setMarkdown("Fine $a^2$, broken $\\frac{1}{2$.");
  const auto state = view.mathsState();
  ASSERT_TRUE(state.ready);
  EXPECT_EQ(state.formulas, 2);
  EXPECT_EQ(state.katexNodes, 1);
  ASSERT_EQ(state.errors.size(), 1);
  EXPECT_TRUE(state.errors.first().contains("KaTeX parse error")) << state.errors.first().toStdString();
  test::takeWarnings();
}
