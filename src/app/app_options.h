// The command line of radiosity-textbook. Without --screenshot the window opens; with it the app renders the
// requested lesson step (or scene) into a PNG and exits, which is the no-display path of the README and the
// way the tests look at the app.
#pragma once

#include <QSize>
#include <QString>
#include <QStringList>
#include <optional>

namespace rt::app {

struct AppOptions {
  QString lesson;      // lesson id; empty: the last position (or the welcome lesson)
  int step = 0;        // 1-based on the command line; 0 = the lesson's first step / the remembered one
  QString scene;       // open a scene file instead of a lesson
  QString screenshot;  // PNG to write, then exit
  QSize size{1600, 1000};
  bool presenter = false;
  bool compare = false;  // also set by any --compare-* option
  // What the right pane changes (--compare-solver, --compare-method, --compare-mesh); empty: the left's.
  QString compareSolver, compareMethod, compareMesh;
};

// Returns the options, or an error message in `error` (then the result is meaningless). --help and --version
// print and exit.
AppOptions parseAppOptions(const QStringList& arguments, QString* error);

// Whether the command line asks for --help (-h, -?) or --version (-v): answered before any window system is
// touched, so that they work without a display.
bool asksForHelpOrVersion(int argc, const char* const* argv);

}  // namespace rt::app
