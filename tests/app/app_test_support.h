// Helpers shared by the app tests: whether an X server is there, Qt warnings collected per test, a main
// window on the repository's lessons (quick parameters), and pixel checks of the 3D views.
#pragma once

#include <QAction>
#include <QImage>
#include <QRect>
#include <QStringList>
#include <functional>
#include <memory>
#include <string>

#include "app/main_window.h"

namespace rt::app::test {

void setDisplayAvailable(bool available);
bool displayAvailable();
// Collects qWarning/qCritical messages (and still prints them).
void installWarningCollector();
QStringList takeWarnings();

// A window over <repo>/lessons and <repo>/scenes, computing on the calling thread unless `threaded`.
std::unique_ptr<MainWindow> makeWindow(bool threaded = false, bool quick = true);
// The number `name` of the step the window shows; -1 when it shows no step or the step does not compute it.
double stepValue(const MainWindow& window, const std::string& name);

// As a reader edits a field: click into `editor` (a spin box or text field), select all, type `text`, press
// Enter, then wait out the panel's pause so that the change is applied (computations run on the test's
// thread).
void typeInto(QWidget* editor, const QString& text);
// A named number of the step the window shows (lesson::StepResult::value); -1 when it has none.
double stepValue(const MainWindow& window, const std::string& name);
// Waits until the parameter panel's pause has passed and its change was applied.
void waitForApply();

// Calls `handle` with the next modal dialog (a file dialog, a message box) once it is open, from the event
// loop that runs it: the way a test answers a dialog that a menu action opens and waits for.
void whenModal(std::function<void(QWidget* dialog)> handle);
// Answers the next save dialog with `path` (typed into its file name field, then Enter) and returns, through
// `suggested`, the name the dialog proposed before.
void answerSaveDialog(const QString& path, QString* suggested);

// The action `text` ("&" ignored) of the menu `menu` ("File", "View") of the window's menu bar, or null.
QAction* menuAction(QWidget& window, const QString& menu, const QString& text);

// Chooses menu > item (> subitem) as a user does: a mouse click on the menu's title in the menu bar, then on
// each item in the menus that open. Returns false, with the reason in *why, when a menu did not open or an
// item is missing, hidden or disabled.
bool clickMenuPath(QWidget& window, const QStringList& path, QString* why = nullptr);

// The rectangle of `widget` inside the window's grab.
QRect areaOf(QWidget* window, QWidget* widget);

// Mean absolute difference per channel (0..255, the worst channel) between `image` and
// tests/baselines/<name>, or -1 when the baseline is missing or of another size. With RT_UPDATE_BASELINES
// set, `image` becomes the baseline (look at it before committing it).
double differenceFromBaseline(const QImage& image, const std::string& name);

}  // namespace rt::app::test

// In a TEST body: skip when there is no X server.
#define RT_REQUIRE_DISPLAY()                                                            \
  do {                                                                                  \
    if (!rt::app::test::displayAvailable()) GTEST_SKIP() << "needs an X server (Xvfb)"; \
  } while (0)
