// The text pane links the first use of each glossary term on a page to its definition, listed under the page
// as the works it cites are: hovering over the term shows the definition, a click scrolls the page to it.
// Driven through the real widget with the mouse.
#include <gtest/gtest.h>

#include <QDir>
#include <QRegularExpression>
#include <QTest>
#include <QWidget>

#include "app/lesson_text_view.h"
#include "app/screenshot.h"
#include "app_test_support.h"
#include "lesson/glossary.h"
#include "support/test_paths.h"

using namespace rt::app;

namespace {

// The definition of `term` in the shipped glossary, as the pane's hover shows it (plain text).
QString definitionOf(const QString& term) {
  for (const auto& e : rt::lesson::loadGlossary(rt::lesson::glossaryPath(rt::test::sourcePath("lessons"))))
    if (QString::fromStdString(e.term) == term) return QString::fromStdString(rt::lesson::definitionText(e));
  return {};
}

// What a widget of the pane (WebEngine's own widget, or the view) offers as its tooltip now.
QString toolTipOf(QWidget* pane) {
  for (QWidget* w : pane->findChildren<QWidget*>())
    if (!w->toolTip().isEmpty()) return w->toolTip();
  return pane->toolTip();
}

}  // namespace

TEST(GlossaryLinks, ATermsFirstUseShowsItsDefinitionOnHoverAndScrollsToItOnClick) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->resize(1600, 1000);
  window->show();
  // The introduction and first step of the form factor chapter: a long page that uses "form factor" early.
  ASSERT_TRUE(window->openLesson("form-factor", 0)) << window->lastError().toStdString();
  LessonTextView* pane = window->textView();
  const QString text = pane->toPlainText();
  const QString definition = definitionOf("form factor");
  ASSERT_FALSE(definition.isEmpty());
  EXPECT_EQ(text.count("href=\"#gl-form-factor\""), 1) << "only the page's first use links";
  EXPECT_TRUE(text.contains("<h3 class=\"terms\">Terms</h3>")) << text.toStdString();
  EXPECT_TRUE(text.contains("<p class=\"glossary\" id=\"gl-form-factor\"><b>form factor</b>: "));
  // Every linked term has its definition on the page, once.
  const QRegularExpression link("href=\"#(gl-[a-z0-9-]+)\"");
  int links = 0;
  for (auto it = link.globalMatch(text); it.hasNext(); ++links) {
    const QString id = it.next().captured(1);
    EXPECT_EQ(text.count("id=\"" + id + "\""), 1) << id.toStdString();
  }
  EXPECT_GE(links, 3);

  const QRect term = pane->linkRect("#gl-form-factor");
  ASSERT_FALSE(term.isEmpty());
  const QRect before = pane->elementRect("gl-form-factor");
  ASSERT_FALSE(before.isNull());
  EXPECT_GT(before.top(), pane->viewport()->height()) << "the definitions start below the fold";

  // Hover: the pane's tooltip is the definition.
  QTest::mouseMove(pane->viewport(), term.center() + QPoint(0, 3));
  QTest::mouseMove(pane->viewport(), term.center());
  for (int k = 0; k < 100 && !toolTipOf(pane).contains(definition.left(40).toHtmlEscaped()); ++k)
    QTest::qWait(50);
  EXPECT_TRUE(toolTipOf(pane).contains(definition.left(40).toHtmlEscaped())) << toolTipOf(pane).toStdString();

  // Click: the page scrolls to the definition, and stays in the app on the same lesson.
  const QString title = window->windowTitle();
  QTest::mouseClick(pane->viewport(), Qt::LeftButton, {}, term.center());
  QRect after;
  for (int k = 0; k < 100; ++k) {
    QTest::qWait(50);
    after = pane->elementRect("gl-form-factor");
    if (!after.isNull() && after.top() >= 0 && after.top() < pane->viewport()->height()) break;
  }
  EXPECT_GE(after.top(), 0);
  EXPECT_LT(after.top(), pane->viewport()->height()) << "the definition is in view after the click";
  EXPECT_EQ(window->windowTitle(), title);
  QDir().mkpath(RT_BINARY_DIR "/tests/screenshots");
  grabWindow(*window).save(RT_BINARY_DIR "/tests/screenshots/glossary-definition.png");
}
