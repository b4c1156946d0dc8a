// The habits of a desktop program: menus that show their shortcuts, Help > Keys with a filter field, Help >
// About, recent files, lesson titles numbered as the texts cite them and never cut without a tooltip.
#include <gtest/gtest.h>

#include <QApplication>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QTableWidget>
#include <QTest>
#include <QTextBrowser>

#include "app/contents_tree.h"
#include "app/keys_dialog.h"
#include "app/lesson_session.h"
#include "app_test_support.h"
#include "lesson/lesson_references.h"
#include "support/test_paths.h"

using namespace rt::app;

TEST(DesktopHabits, MenusShowTheirShortcuts) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const std::vector<std::pair<QString, QString>> expected{
      {"File", "Open scene..."},  {"File", "Export view (PNG, SVG, PDF)..."},
      {"File", "Quit"},           {"Edit", "Undo"},
      {"Edit", "Redo"},           {"Go", "Next step"},
      {"Go", "Previous step"},    {"Go", "Play / pause iterations"},
      {"Go", "Next iteration"},   {"Go", "Compute this step"},
      {"View", "Presenter mode"}, {"View", "Zoom text in"},
      {"View", "Zoom text out"},  {"View", "Reset view"},
      {"View", "Front view"},     {"View", "Top view"},
      {"View", "Side view"},      {"View", "Step figure in the main pane"},
      {"Help", "Keys..."}};
  for (const auto& [menu, text] : expected) {
    QAction* action = test::menuAction(*window, menu, text);
    ASSERT_NE(action, nullptr) << menu.toStdString() << " > " << text.toStdString();
    EXPECT_FALSE(action->shortcut().isEmpty()) << text.toStdString() << " shows no shortcut";
  }
  EXPECT_EQ(test::menuAction(*window, "Edit", "Redo")->shortcut(), QKeySequence("Ctrl+Shift+Z"));
}

TEST(DesktopHabits, MenuItemsChosenWithTheMouseAct) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  ASSERT_TRUE(window->openLesson("gathering", 0));
  ASSERT_TRUE(window->waitUntilIdle());
  QString why;
  ASSERT_TRUE(test::clickMenuPath(*window, {"Go", "Next step"}, &why)) << why.toStdString();
  ASSERT_TRUE(window->waitUntilIdle());
  EXPECT_EQ(window->currentStep(), 1);
  ASSERT_TRUE(test::clickMenuPath(*window, {"Go", "Previous step"}, &why)) << why.toStdString();
  ASSERT_TRUE(window->waitUntilIdle());
  EXPECT_EQ(window->currentStep(), 0);
  ASSERT_TRUE(test::clickMenuPath(*window, {"View", "Presenter mode"}, &why)) << why.toStdString();
  EXPECT_TRUE(window->presenterMode());
  window->setPresenterMode(false);
}

TEST(DesktopHabits, HelpKeysListsEveryKeyAndFilters) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("gathering", 0));
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  QTest::keyClick(window.get(), Qt::Key_F1);
  auto* dialog = window->findChild<KeysDialog*>();
  ASSERT_NE(dialog, nullptr) << "F1 opened no list of keys";
  ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
  const int all = dialog->visibleRows();
  EXPECT_GT(all, 15);
  QTest::keyClicks(dialog->filterField(), "zoom");
  EXPECT_GE(dialog->visibleRows(), 3);  // the text's zoom keys and the 3D view's wheel
  EXPECT_LT(dialog->visibleRows(), all);
  for (int row = 0; row < dialog->table()->rowCount(); ++row) {
    if (dialog->table()->isRowHidden(row)) continue;
    const QString line = dialog->table()->item(row, 0)->text() + " " + dialog->table()->item(row, 1)->text();
    EXPECT_TRUE(line.contains("zoom", Qt::CaseInsensitive)) << line.toStdString();
  }
  dialog->filterField()->clear();
  QTest::keyClicks(dialog->filterField(), "Ctrl+Shift+Z");
  EXPECT_EQ(dialog->visibleRows(), 1);
  dialog->close();
}

TEST(DesktopHabits, HelpAboutNamesTheProgram) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  QString text;
  test::whenModal([&text](QWidget* dialog) {
    if (auto* box = qobject_cast<QMessageBox*>(dialog)) text = box->text();
    dialog->close();
  });
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  QString why;
  ASSERT_TRUE(test::clickMenuPath(*window, {"Help", "About Radiosity Textbook"}, &why)) << why.toStdString();
  EXPECT_TRUE(text.contains("Radiosity Textbook")) << text.toStdString();
  EXPECT_TRUE(text.contains("lessons")) << text.toStdString();
}

TEST(DesktopHabits, RecentFilesReopenAScene) {
  RT_REQUIRE_DISPLAY();
  QSettings().remove("recent/files");
  auto window = test::makeWindow();
  const QString squares = QString::fromStdString(RT_SOURCE_DIR "/scenes/parallel-squares.json");
  ASSERT_TRUE(window->openScene(squares));
  ASSERT_TRUE(window->openScene(QString()));  // the built-in box is no file: not in the list
  ASSERT_EQ(window->recentFiles().size(), 1);
  auto* recent = window->findChild<QMenu*>("recentMenu");
  ASSERT_NE(recent, nullptr);
  ASSERT_GE(recent->actions().size(), 1);
  QAction* first = recent->actions().front();
  EXPECT_TRUE(first->text().contains("parallel-squares.json")) << first->text().toStdString();
  // Chosen with the mouse: File, then the submenu, then the file.
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  QString why;
  ASSERT_TRUE(test::clickMenuPath(
      *window, {"File", recent->title().remove('&'), QString(first->text()).remove('&')}, &why))
      << why.toStdString();
  ASSERT_TRUE(window->waitUntilIdle());
  ASSERT_NE(window->result(), nullptr);
  EXPECT_EQ(window->result()->scene->patches.size(), 2u);
  QSettings().remove("recent/files");
}

TEST(DesktopHabits, LessonsAreNumberedAsTheTextsCiteThem) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openLesson("ray-casting", 0));
  // "@Lesson:ray-casting estimated form factors by sampling" (the stochastic lesson) reads "Lesson N", N the
  // ray-casting lesson's order: the contents say "Lesson N" too.
  const QString number =
      QString("Lesson %1:").arg(rt::lesson::lessonNumbers(rt::test::sourcePath("lessons")).at("ray-casting"));
  const auto items = window->contents()->findItems(number, Qt::MatchStartsWith | Qt::MatchRecursive);
  ASSERT_EQ(items.size(), 1);
  EXPECT_TRUE(items.front()->text(0).contains("Ray casting")) << items.front()->text(0).toStdString();
  EXPECT_FALSE(items.front()->toolTip(0).isEmpty());
  for (int k = 0; k < items.front()->childCount(); ++k)
    EXPECT_TRUE(items.front()->child(k)->toolTip(0).contains(items.front()->child(k)->text(0)));
  // The step label under the text: numbered too, wrapped rather than cut, with a tooltip.
  QLabel* label = nullptr;
  for (QLabel* l : window->findChildren<QLabel*>())
    if (l->text().contains("step 1 of")) label = l;
  ASSERT_NE(label, nullptr);
  EXPECT_TRUE(label->text().startsWith(number + " Ray casting")) << label->text().toStdString();
  EXPECT_TRUE(label->wordWrap());
  EXPECT_FALSE(label->toolTip().isEmpty());
  EXPECT_TRUE(window->windowTitle().startsWith(number));
}

TEST(DesktopHabits, AReferenceToAnotherLessonOpensItWhenClicked) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  window->show();
  // The rendering equation's introduction says "Lesson 2 derives these quantities" (written
  // @Lesson:measuring-light): the number is the chapter's, and the link opens it here, not in a browser.
  ASSERT_TRUE(window->openLesson("rendering-equation", 0)) << window->lastError().toStdString();
  EXPECT_TRUE(window->textView()->toPlainText().contains("[Lesson 2](measuring-light.html#top)"));
  const QRect link = window->textView()->linkRect("measuring-light.html#top");
  ASSERT_FALSE(link.isEmpty());
  QTest::mouseClick(window->textView()->viewport(), Qt::LeftButton, {}, link.center());
  for (int k = 0; k < 100 && !window->windowTitle().startsWith("Lesson 2:"); ++k) QTest::qWait(50);
  EXPECT_TRUE(window->windowTitle().startsWith("Lesson 2: Measuring light"))
      << window->windowTitle().toStdString();
}
