// radiosity-textbook: parses the command line, opens the main window; with --screenshot renders it into a PNG
// and exits (the no-display path: run it under xvfb-run).
#include <QApplication>
#include <QTimer>
#include <cstdio>
#include <cstdlib>

#include "app/app_options.h"
#include "app/lesson_session.h"
#include "app/main_window.h"
#include "app/screenshot.h"
#include "app/vtk_widget.h"
#include "core/vector_state.h"
#include "typeset/web_engine.h"

namespace {

void nameTheApplication() {
  QCoreApplication::setOrganizationName("RadiosityTextbook");
  QCoreApplication::setApplicationName("radiosity-textbook");
  QCoreApplication::setApplicationVersion("0.1.0");
}

// Shows the window: writes the screenshot and returns, or runs until the reader closes it. The exit status.
int runWindow(rt::app::MainWindow& window, const rt::app::AppOptions& options) {
  if (!options.screenshot.isEmpty()) {
    window.setBlockingComputations(true);
    window.show();
    if (!window.start()) {
      std::fprintf(stderr, "radiosity-textbook: %s\n", qPrintable(window.lastError()));
      return 1;
    }
    rt::app::saveScreenshot(window, options.screenshot);
    if (!window.lastError().isEmpty()) {
      std::fprintf(stderr, "radiosity-textbook: %s\n", qPrintable(window.lastError()));
      return 1;
    }
    std::fprintf(stderr, "screenshot written to %s\n", qPrintable(options.screenshot));
    return 0;
  }
  window.show();
  QTimer::singleShot(0, &window, [&window] { window.start(); });
  return QApplication::exec();
}

}  // namespace

int main(int argc, char** argv) {
  if (rt::app::asksForHelpOrVersion(argc, argv)) {
    // Answered without a window system (a terminal with no display, a script): QApplication would need one.
    QCoreApplication core(argc, argv);
    nameTheApplication();
    QString error;
    rt::app::parseAppOptions(QCoreApplication::arguments(), &error);  // prints and exits
    std::fprintf(stderr, "radiosity-textbook: %s\n", qPrintable(error));
    return 2;
  }
  // Before any thread exists: the threads made later start from this state (core/vector_state.h).
  rt::clearUpperVectorState();
  // VTK needs its GL context profile decided before any Qt GL object exists.
  rt::app::VtkWidget::setDefaultSurfaceFormat();
  // The text pane is a web view (typeset maths): WebEngine's settings come before the application object too.
  rt::typeset::prepareWebEngine();
  QApplication app(argc, argv);
  nameTheApplication();

  QString error;
  const rt::app::AppOptions options = rt::app::parseAppOptions(QApplication::arguments(), &error);
  if (!error.isEmpty()) {
    std::fprintf(stderr, "radiosity-textbook: %s\n", qPrintable(error));
    return 2;
  }

  int status = 0;
  try {
    {
      rt::app::MainWindow window(options);
      status = runWindow(window, options);
    }
    rt::typeset::releaseDeletedWebViews();  // before the application goes
  } catch (const std::exception& e) {
    std::fprintf(stderr, "radiosity-textbook: %s\n", e.what());
    return 1;
  }
  // The window is closed and its settings written (each QSettings is synced where it goes out of scope): the
  // process ends without the application's and the libraries' teardown, where Chromium's and the GL
  // driver's clean-up now and then found the heap corrupted and crashed a run that had done its work.
  std::fflush(nullptr);
  std::_Exit(status);
}
