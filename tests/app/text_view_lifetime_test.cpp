// The text pane asks its page to typeset the maths and waits for the answer. WebEngine answers every pending
// question when the page is deleted, so a pane closed while its page typesets (the window closed, the app
// quit) must take that late answer without touching what it has already destroyed: before, it wrote into
// destroyed members and emitted its signal, and the heap was found corrupted at exit.
#include <gtest/gtest.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include "app/lesson_text_view.h"
#include "app_test_support.h"

using namespace rt::app;

namespace {

void wait(int ms) {
  QEventLoop loop;
  QTimer::singleShot(ms, &loop, &QEventLoop::quit);
  loop.exec();
}

QString manyFormulas() {
  QString markdown = "# Maths\n\n";
  for (int k = 0; k < 200; ++k)
    markdown += QString("$$B_{%1} = E_{%1} + \\rho_{%1} \\sum_j F_{%1 j} B_j$$\n\n").arg(k);
  return markdown;
}

}  // namespace

TEST(TextViewLifetime, APaneClosedWhileItsPageTypesetsIgnoresTheLateAnswer) {
  RT_REQUIRE_DISPLAY();
  // Closed at several moments after the text is set, so that some close while the typesetting script runs.
  int answersAfterClose = 0;
  for (int delay : {0, 30, 60, 90, 120, 160, 200, 260, 330, 400}) {
    auto* view = new LessonTextView;
    view->resize(800, 600);
    view->show();
    bool closing = false;
    QObject receiver;
    QObject::connect(view, &LessonTextView::typeset, &receiver, [&](int, const QStringList&) {
      if (closing) ++answersAfterClose;
    });
    view->setMarkdown(manyFormulas());
    wait(delay);
    closing = true;
    delete view;
    QApplication::processEvents();
  }
  EXPECT_EQ(answersAfterClose, 0) << "a closed pane reported a typeset page";
  // The pane still works when it is left open.
  LessonTextView view;
  view.resize(800, 600);
  view.show();
  view.setMarkdown(manyFormulas());
  const LessonTextView::MathsState state = view.mathsState(30000);
  ASSERT_TRUE(state.ready);
  EXPECT_EQ(state.formulas, 200);
  EXPECT_TRUE(state.errors.isEmpty());
}

TEST(TextViewLifetime, AnAnswerAfterTheTimeoutIsDropped) {
  RT_REQUIRE_DISPLAY();
  LessonTextView view;
  view.resize(800, 600);
  view.show();
  view.setMarkdown("Text.");
  ASSERT_TRUE(view.waitUntilShown());
  // A timeout of 0 returns before the page answers; the answer comes later, into a frame that is gone.
  for (int k = 0; k < 20; ++k) {
    const QRect none = view.elementRect("no-such-element", 0);
    EXPECT_TRUE(none.isEmpty());
  }
  wait(300);  // the late answers arrive here
  EXPECT_TRUE(view.elementRect("no-such-element", 5000).isEmpty());
  EXPECT_TRUE(view.mathsState().ready);
}
