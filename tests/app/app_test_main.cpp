// The app tests need a QApplication and an X server (QOpenGLWidget and VTK's GLX window have no headless
// mode). Without DISPLAY the binary runs itself again under xvfb-run, so that `ctest` works on a machine
// without a screen.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>
#include <QApplication>
#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "app/vtk_widget.h"
#include "app_test_support.h"
#include "typeset/web_engine.h"

namespace {

bool listingOnly(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--gtest_list_tests") == 0) return true;
  return false;
}

void reexecUnderXvfb(const std::vector<std::string>& original) {
  if (std::getenv("RT_APP_TESTS_UNDER_XVFB")) return;  // already tried: do not loop
  setenv("RT_APP_TESTS_UNDER_XVFB", "1", 1);
  std::vector<std::string> args{"xvfb-run", "-a", "-s", "-screen 0 1920x1080x24"};
  args.insert(args.end(), original.begin(), original.end());
  std::vector<char*> raw;
  for (auto& a : args) raw.push_back(a.data());
  raw.push_back(nullptr);
  execvp("xvfb-run", raw.data());  // returns only on failure: the tests then skip
}

// After each test, whose window is gone by then, what its web view left to deleteLater goes while the
// application exists (typeset::releaseDeletedWebViews).
class ReleaseWebViews : public testing::EmptyTestEventListener {
  void OnTestEnd(const testing::TestInfo&) override { rt::typeset::releaseDeletedWebViews(); }
};

}  // namespace

int main(int argc, char** argv) {
  // Before InitGoogleTest, which consumes the gtest flags.
  const bool listing = listingOnly(argc, argv);
  const std::vector<std::string> original(argv, argv + argc);
  testing::InitGoogleTest(&argc, argv);
  if (listing) return RUN_ALL_TESTS();
  if (!std::getenv("DISPLAY")) reexecUnderXvfb(original);
  if (!std::getenv("DISPLAY")) {
    rt::app::test::setDisplayAvailable(false);
    setenv("QT_QPA_PLATFORM", "offscreen", 1);
  }
  if (!std::getenv("XDG_RUNTIME_DIR")) {
    const std::string dir = "/tmp/rt-app-tests-" + std::to_string(getuid());
    mkdir(dir.c_str(), 0700);
    setenv("XDG_RUNTIME_DIR", dir.c_str(), 1);
  }
  rt::app::VtkWidget::setDefaultSurfaceFormat();
  rt::typeset::prepareWebEngine();
  QApplication app(argc, argv);
  // Settings (the remembered position) go to a test location, never the user's, and one file per process:
  // ctest runs the tests of this binary as concurrent processes, which must not see each other's position.
  QStandardPaths::setTestModeEnabled(true);
  QApplication::setOrganizationName("RadiosityTextbookTests");
  QApplication::setApplicationName(QString("app_tests-%1").arg(QApplication::applicationPid()));
  rt::app::test::installWarningCollector();
  testing::UnitTest::GetInstance()->listeners().Append(new ReleaseWebViews);
  const int status = RUN_ALL_TESTS();
  QFile::remove(QSettings().fileName());
  // The results are in: the process ends here, without the application's and the libraries' teardown.
  // Chromium's and the GL driver's teardown at exit now and then found the heap corrupted after every test
  // had passed (about one process in sixty, never while a test ran), and that would fail a passing test.
  std::fflush(nullptr);
  std::_Exit(status);
}
