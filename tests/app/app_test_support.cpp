#include "app_test_support.h"

#include <QApplication>
#include <QFileDialog>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMutex>
#include <QTest>
#include <QTimer>
#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "lesson/step_result.h"

#include "app/lesson_session.h"
#include "lesson/step_result.h"
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

double stepValue(const MainWindow& window, const std::string& name) {
  const PipelineResult* r = window.result();
  if (!r || !r->stepResult) return -1;
  return static_cast<const lesson::StepResult*>(r->stepResult.get())->value(name).value_or(-1);
}

void typeInto(QWidget* editor, const QString& text) {
  if (!editor) throw std::runtime_error("typeInto: no editor");
  editor->setFocus();
  QTest::mouseClick(editor, Qt::LeftButton);
  QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(editor, text);
  QTest::keyClick(editor, Qt::Key_Return);
  waitForApply();
}

void waitForApply() {
  QTest::qWait(450);  // the panel applies 350 ms after the last edit
  QTest::qWait(50);   // and the views repaint
}

void whenModal(std::function<void(QWidget* dialog)> handle) {
  auto* timer = new QTimer();
  timer->setInterval(20);
  QObject::connect(timer, &QTimer::timeout, [timer, handle] {
    QWidget* dialog = QApplication::activeModalWidget();
    if (!dialog || !dialog->isVisible()) return;
    timer->stop();
    timer->deleteLater();
    handle(dialog);
  });
  timer->start();
}

void answerSaveDialog(const QString& path, QString* suggested) {
  whenModal([path, suggested](QWidget* dialog) {
    auto* files = qobject_cast<QFileDialog*>(dialog);
    if (!files) {
      dialog->close();
      return;
    }
    auto* name = files->findChild<QLineEdit*>("fileNameEdit");
    if (suggested) *suggested = name ? name->text() : QString();
    if (!name) {
      files->reject();
      return;
    }
    // The whole path at once (typed letter by letter, the field's completer would open a list that takes
    // the Enter key), then Enter as the reader presses it.
    name->setFocus();
    name->setText(path);
    QTest::keyClick(name, Qt::Key_Return);
    // Whatever else the dialog still wants (it should not), it must not hang the test.
    if (files->isVisible()) files->reject();
  });
}

QAction* menuAction(QWidget& window, const QString& menu, const QString& text) {
  auto* bar = window.findChild<QMenuBar*>();
  if (!bar) return nullptr;
  for (QAction* top : bar->actions()) {
    if (!top->menu() || QString(top->text()).remove('&') != menu) continue;
    for (QAction* action : top->menu()->actions())
      if (QString(action->text()).remove('&') == text) return action;
  }
  return nullptr;
}

namespace {

QAction* itemNamed(QWidget* menu, const QString& text) {
  for (QAction* action : menu->actions())
    if (QString(action->text()).remove('&') == text) return action;
  return nullptr;
}

}  // namespace

bool clickMenuPath(QWidget& window, const QStringList& path, QString* why) {
  auto fail = [why](const QString& reason) {
    if (why) *why = reason;
    QWidget* popup = QApplication::activePopupWidget();
    while (popup) {  // close what opened, so the next test starts clean
      popup->close();
      popup = QApplication::activePopupWidget();
    }
    return false;
  };
  auto* bar = window.findChild<QMenuBar*>();
  if (!bar || !bar->isVisible()) return fail("no visible menu bar");
  window.activateWindow();
  QApplication::setActiveWindow(&window);
  QAction* top = itemNamed(bar, path.front());
  if (!top || !top->menu()) return fail("no menu " + path.front());
  QTest::mouseClick(bar, Qt::LeftButton, {}, bar->actionGeometry(top).center());
  QMenu* menu = top->menu();
  if (!QTest::qWaitFor([menu] { return menu->isVisible(); }, 2000))
    return fail(path.front() + " did not open");
  for (qsizetype k = 1; k < path.size(); ++k) {
    QAction* item = itemNamed(menu, path[k]);
    if (!item || !item->isVisible() || !item->isEnabled())
      return fail(path[k] + " is missing, hidden or disabled in " + path[k - 1]);
    const QPoint at = menu->actionGeometry(item).center();
    QTest::mouseMove(menu, at);
    QTest::mouseClick(menu, Qt::LeftButton, {}, at);
    if (k + 1 < path.size()) {
      menu = item->menu();
      if (!menu || !QTest::qWaitFor([menu] { return menu->isVisible(); }, 2000))
        return fail(path[k] + " opened no submenu");
    }
  }
  QApplication::processEvents();
  return true;
}

QRect areaOf(QWidget* window, QWidget* widget) {
  return QRect(widget->mapTo(window, QPoint(0, 0)), widget->size());
}

double differenceFromBaseline(const QImage& image, const std::string& name) {
  const QString path = QString::fromStdString(rt::test::sourcePath("tests/baselines/" + name));
  if (std::getenv("RT_UPDATE_BASELINES")) return image.save(path) ? 0.0 : -1.0;
  const QImage baseline(path);
  if (baseline.isNull() || baseline.size() != image.size()) return -1;
  const QImage a = image.convertToFormat(QImage::Format_RGB32);
  const QImage b = baseline.convertToFormat(QImage::Format_RGB32);
  double sum[3] = {0, 0, 0};
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
      sum[0] += std::abs(qRed(p) - qRed(q));
      sum[1] += std::abs(qGreen(p) - qGreen(q));
      sum[2] += std::abs(qBlue(p) - qBlue(q));
    }
  const double pixels = static_cast<double>(a.width()) * a.height();
  return std::max({sum[0], sum[1], sum[2]}) / pixels;
}

}  // namespace rt::app::test
