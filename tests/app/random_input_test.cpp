// A reader who does anything, in any order: random shortcuts, drags, wheel turns and clicks on the 3D view,
// edits of the parameter panel's widgets, answers typed into exercises, jumps to any step. Computations run
// on their own thread as in the app. A hang is a wait for the window to become idle that outlasts two
// minutes; a crash ends the process. Every action is printed before it is made, after the seed, so a failure
// can be replayed with the same seed:
//   RT_RANDOM_INPUT_SEED=S RT_RANDOM_INPUT_SECONDS=600 xvfb-run -a -s "-screen 0 1920x1080x24 -noreset"
//     build/release/tests/app_tests --gtest_filter='RandomInput.*'
// (tests/app/random_input.sh runs the ten-minute version.) The test suite runs it for 20 s by default.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTest>
#include <QTimer>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "app/exercise_panel.h"
#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app_test_support.h"

using namespace rt::app;

namespace {

long environmentNumber(const char* name, long fallback) {
  const char* text = std::getenv(name);
  return text && *text ? std::strtol(text, nullptr, 10) : fallback;
}

// The window's shortcuts, less those that open a dialog or end the program (a random reader would not
// answer a file dialog; a dialog that opens anyway is closed by the watcher below).
std::vector<QAction*> shortcutActions(QWidget& window) {
  std::vector<QAction*> actions;
  for (QAction* action : window.findChildren<QAction*>()) {
    const QString text = action->text();
    if (action->shortcut().isEmpty() || text.contains("...") || text.contains("Quit") ||
        text.contains("Export"))
      continue;
    actions.push_back(action);
  }
  return actions;
}

// A modal dialog as one line: its kind, title and, for a message box, its text.
std::string describeDialog(QWidget* dialog) {
  QString line = QString("%1 \"%2\"").arg(dialog->metaObject()->className(), dialog->windowTitle());
  if (auto* box = qobject_cast<QMessageBox*>(dialog)) {
    line += ": " + box->text();
    if (!box->informativeText().isEmpty()) line += " / " + box->informativeText();
    if (!box->detailedText().isEmpty()) line += " / " + box->detailedText();
  }
  return line.simplified().toStdString();
}

template <class Widget>
std::vector<Widget*> visibleEnabled(QWidget* parent) {
  std::vector<Widget*> found;
  if (!parent) return found;
  for (Widget* widget : parent->findChildren<Widget*>())
    if (widget->isVisible() && widget->isEnabled()) found.push_back(widget);
  return found;
}

class RandomReader {
 public:
  RandomReader(MainWindow& window, unsigned seed) : window_(window), random_(seed) {
    actions_ = shortcutActions(window);
  }

  // Makes one random action and returns what it was.
  std::string act() {
    switch (pick(8)) {
      case 0:
      case 1:
        return shortcut();
      case 2:
        return dragView();
      case 3:
        return wheelOrClickView();
      case 4:
      case 5:
        return editParameter();
      case 6:
        return answerExercise();
      default:
        return jump();
    }
  }

 private:
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(random_); }

  std::string shortcut() {
    if (actions_.empty()) return "no shortcut";
    QAction* action = actions_[pick(static_cast<int>(actions_.size()))];
    const QKeySequence keys = action->shortcut();
    window_.activateWindow();
    QTest::keySequence(&window_, keys);
    return "key " + keys.toString().toStdString() + " (" + action->text().toStdString() + ")";
  }

  QPoint pointIn(QWidget* widget) {
    return QPoint(1 + pick(std::max(1, widget->width() - 2)), 1 + pick(std::max(1, widget->height() - 2)));
  }

  std::string dragView() {
    SceneView* view = window_.primaryView();
    if (!view || !view->isVisible()) return "no view to drag";
    const QPoint from = pointIn(view), to = pointIn(view);
    QTest::mousePress(view, Qt::LeftButton, {}, from);
    QTest::mouseMove(view, (from + to) / 2);
    QTest::mouseMove(view, to);
    QTest::mouseRelease(view, Qt::LeftButton, {}, to);
    return "drag the 3D view";
  }

  std::string wheelOrClickView() {
    SceneView* view = window_.primaryView();
    if (!view || !view->isVisible()) return "no view to click";
    const QPoint at = pointIn(view);
    if (pick(2) == 0) {
      QTest::mouseClick(view, Qt::LeftButton, {}, at);
      return "click the 3D view";
    }
    QWheelEvent wheel(at, view->mapToGlobal(at), QPoint(), QPoint(0, pick(2) ? 120 : -120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view, &wheel);
    return "wheel over the 3D view";
  }

  std::string editParameter() {
    QWidget* panel = window_.parameterPanel();
    auto spins = visibleEnabled<QAbstractSpinBox>(panel);
    auto combos = visibleEnabled<QComboBox>(panel);
    auto checks = visibleEnabled<QCheckBox>(panel);
    const int total = static_cast<int>(spins.size() + combos.size() + checks.size());
    if (total == 0) return "no parameter offered";
    int k = pick(total);
    if (k < static_cast<int>(spins.size())) {
      QAbstractSpinBox* spin = spins[k];
      const Qt::Key key = pick(2) ? Qt::Key_Up : Qt::Key_Down;
      spin->setFocus();
      for (int n = 1 + pick(3); n > 0; --n) QTest::keyClick(spin, key);
      QTest::keyClick(spin, Qt::Key_Return);
      return "step the box " + spin->objectName().toStdString() + (key == Qt::Key_Up ? " up" : " down");
    }
    k -= static_cast<int>(spins.size());
    if (k < static_cast<int>(combos.size())) {
      QComboBox* combo = combos[k];
      if (combo->count() > 0) combo->setCurrentIndex(pick(combo->count()));
      return "choose item " + std::to_string(combo->currentIndex()) + " of " +
             combo->objectName().toStdString();
    }
    QCheckBox* check = checks[k - combos.size()];
    QTest::mouseClick(check, Qt::LeftButton, {}, QPoint(4, check->height() / 2));
    return "toggle " + check->text().toStdString();
  }

  std::string answerExercise() {
    QWidget* exercise = window_.exercisePanel();
    auto fields = visibleEnabled<QLineEdit>(exercise);
    if (fields.empty()) return "no exercise";
    QLineEdit* field = fields[pick(static_cast<int>(fields.size()))];
    const char* answers[] = {"0.5", "-1", "1e300", "abc", "", "3.21674", "nan", "0"};
    field->setFocus();
    field->selectAll();
    QTest::keyClicks(field, answers[pick(8)]);
    for (QPushButton* button : visibleEnabled<QPushButton>(exercise))
      if (button->text().contains("Check") && pick(2) == 0) QTest::mouseClick(button, Qt::LeftButton);
    return "type an answer";
  }

  std::string jump() {
    const int lessons = static_cast<int>(window_.library()->lessons().size());
    const int lesson = pick(lessons);
    const int steps = static_cast<int>(window_.library()->lessons()[lesson].steps.size());
    const int step = pick(std::max(1, steps));
    window_.openStep(lesson, step);
    return "open lesson " + window_.library()->lessons()[lesson].id + " step " + std::to_string(step + 1);
  }

  MainWindow& window_;
  std::mt19937 random_;
  std::vector<QAction*> actions_;
};

}  // namespace

TEST(RandomInput, NoCrashNoHang) {
  RT_REQUIRE_DISPLAY();
  const unsigned seed =
      static_cast<unsigned>(environmentNumber("RT_RANDOM_INPUT_SEED", std::random_device{}()));
  const long seconds = environmentNumber("RT_RANDOM_INPUT_SECONDS", 20);
  std::printf("random input: seed %u, %ld s (replay: RT_RANDOM_INPUT_SEED=%u)\n", seed, seconds, seed);
  auto window = test::makeWindow(/*threaded=*/true, /*quick=*/true);
  window->resize(1600, 1000);
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  ASSERT_TRUE(window->openLesson("gathering", 0));
  ASSERT_TRUE(window->waitUntilIdle());

  // A dialog that an action opens (an error message, say) is printed, so that what a reader met can be
  // examined, then closed, as a reader would.
  int dialogsClosed = 0;
  long count = 0;
  QTimer watcher;
  QObject::connect(&watcher, &QTimer::timeout, [&] {
    if (QWidget* modal = QApplication::activeModalWidget()) {
      std::printf("dialog after action %ld: %s\n", count, describeDialog(modal).c_str());
      std::fflush(stdout);
      modal->close();
      ++dialogsClosed;
    }
  });
  watcher.start(200);

  RandomReader reader(*window, seed);
  QElapsedTimer clock;
  clock.start();
  while (clock.elapsed() < seconds * 1000) {
    const std::string what = reader.act();
    ++count;
    std::printf("%ld: %s\n", count, what.c_str());
    std::fflush(stdout);
    // Some actions only start a computation; a reader keeps going, so the wait is only for a hang.
    ASSERT_TRUE(window->waitUntilIdle(120000))
        << "hang after action " << count << " (" << what << "), seed " << seed;
    QApplication::processEvents();
  }
  std::printf("random input: seed %u, %ld actions in %.0f s, %d dialogs closed, no crash, no hang\n", seed,
              count, clock.elapsed() / 1000.0, dialogsClosed);
  EXPECT_GT(count, 10);
}
