#include "app_test_support.h"

#include <QApplication>
#include <QMutex>

#include "app/lesson_session.h"
#include "support/test_paths.h"

namespace rt::app::test {
namespace {

bool display = true;
QStringList warnings;
QMutex warningsMutex;
QtMessageHandler previousHandler = nullptr;

void collect(QtMsgType type, const QMessageLogContext& context, const QString& message) {
  if (type == QtWarningMsg || type == QtCriticalMsg || type == QtFatalMsg) {
    QMutexLocker lock(&warningsMutex);
    warnings << message;
  }
  if (previousHandler) previousHandler(type, context, message);
}

}  // namespace

void setDisplayAvailable(bool available) {
  display = available;
}
bool displayAvailable() {
  return display;
}

void installWarningCollector() {
  previousHandler = qInstallMessageHandler(collect);
}

QStringList takeWarnings() {
  QMutexLocker lock(&warningsMutex);
  QStringList out = warnings;
  warnings.clear();
  return out;
}

std::unique_ptr<MainWindow> makeWindow(bool threaded, bool quick) {
  lesson::RunOptions options;
  options.quick = quick;
  auto library = std::make_unique<LessonLibrary>(lesson::foldersUnder(rt::test::sourcePath("")), options);
  AppOptions appOptions;
  appOptions.size = QSize(1400, 900);
  auto window = std::make_unique<MainWindow>(appOptions, std::move(library));
  window->setBlockingComputations(!threaded);
  window->show();
  QApplication::processEvents();
  return window;
}

QRect areaOf(QWidget* window, QWidget* widget) {
  return QRect(widget->mapTo(window, QPoint(0, 0)), widget->size());
}

}  // namespace rt::app::test
