#include "typeset/web_engine.h"

#include <unistd.h>
#include <QCoreApplication>
#include <QDir>
#include <QEventLoop>
#include <QFile>
#include <QGuiApplication>
#include <QLoggingCategory>
#include <QPageLayout>
#include <QPageSize>
#include <QTimer>
#include <QWebEnginePage>
#include <cstdlib>

namespace rt::typeset {

void prepareWebEngine() {
  if (geteuid() == 0 && qEnvironmentVariableIsEmpty("QTWEBENGINE_DISABLE_SANDBOX"))
    qputenv("QTWEBENGINE_DISABLE_SANDBOX", "1");
  QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
  // Text and maths, laid out or printed, need no GPU. With it, Chromium reads the 3D view's default surface
  // format (a core profile), reports that it falls back from it, and its GPU process sometimes reports a
  // transient failure at start: harmless, but on every start's stderr. Without it neither is printed, and
  // Qt's and Chromium's descriptions of their set-up are silenced too.
  if (qEnvironmentVariableIsEmpty("QTWEBENGINE_CHROMIUM_FLAGS"))
    qputenv("QTWEBENGINE_CHROMIUM_FLAGS", "--disable-gpu --disable-logging --log-level=3");
  // As rules, not as QT_LOGGING_RULES: the registry may have read the environment already (the 3D view's
  // surface format is set first), and a reader's own QT_LOGGING_RULES still takes precedence over these.
  QLoggingCategory::setFilterRules("qt.webenginecontext.info=false\nqt.webenginecontext.debug=false");
}

void releaseDeletedWebViews() {
  // Deleting one part queues the deletion of others, and Chromium answers on its own threads: a few rounds.
  for (int round = 0; round < 4; ++round) {
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    QCoreApplication::processEvents(QEventLoop::AllEvents, 25);
  }
}

QString katexDirectory() {
  const QString configured = qEnvironmentVariable("RT_KATEX_DIR");
  return configured.isEmpty() ? QString(RT_KATEX_DIR) : configured;
}

QString typesetScript() {
  return QStringLiteral(R"JS((function () {
  var errors = [];
  var nodes = Array.prototype.slice.call(document.querySelectorAll('x-equation'));
  nodes.forEach(function (node) {
    var tex = node.textContent;
    var span = document.createElement('span');
    try {
      katex.render(tex, span, {displayMode: node.getAttribute('type') === 'display', throwOnError: true});
    } catch (e) {
      errors.push(String(e.message));
      span.className = 'katex-error';
      span.title = String(e.message);
      span.textContent = tex;
    }
    // HTML needs no namespace on <math>: without it the page names no address at all.
    Array.prototype.forEach.call(span.querySelectorAll('math'), function (m) { m.removeAttribute('xmlns'); });
    node.parentNode.replaceChild(span, node);
  });
  window.rtMaths = {formulas: nodes.length, errors: errors};
  return JSON.stringify(window.rtMaths);
})())JS");
}

WebSession::WebSession() {
  if (QCoreApplication::instance()) return;
  if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", "offscreen");
  if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
    const QByteArray dir = "/tmp/runtime-" + QByteArray::number(getuid());
    QDir().mkpath(QString::fromUtf8(dir));
    QFile::setPermissions(QString::fromUtf8(dir),
                          QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    qputenv("XDG_RUNTIME_DIR", dir);
  }
  prepareWebEngine();
  static int argc = 1;
  static char name[] = "radiosity";
  static char* argv[] = {name, nullptr};
  app_ = std::make_unique<QGuiApplication>(argc, argv);
}

WebSession::~WebSession() = default;

SyncPage::SyncPage() : page_(std::make_unique<QWebEnginePage>()) {
  QObject::connect(page_.get(), &QWebEnginePage::loadFinished, [this](bool ok) {
    loaded_ = true;
    ok_ = ok;
  });
}

SyncPage::~SyncPage() = default;

bool SyncPage::waitForLoad() {
  QEventLoop loop;
  QTimer poll;
  QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
    if (loaded_) loop.quit();
  });
  poll.start(10);
  QTimer::singleShot(60000, &loop, &QEventLoop::quit);  // a local page loads in well under a second
  loop.exec();
  return loaded_ && ok_;
}

bool SyncPage::setHtml(const QString& html, const QUrl& baseUrl) {
  loaded_ = false;
  page_->setHtml(html, baseUrl);
  return waitForLoad();
}

bool SyncPage::load(const QUrl& url) {
  loaded_ = false;
  page_->load(url);
  return waitForLoad();
}

QVariant SyncPage::run(const QString& script) {
  QEventLoop loop;
  QVariant result;
  page_->runJavaScript(script, [&](const QVariant& value) {
    result = value;
    loop.quit();
  });
  loop.exec();
  return result;
}

bool SyncPage::waitFor(const QString& condition, int timeoutMs) {
  for (int waited = 0; waited <= timeoutMs; waited += 25) {
    if (run(condition).toBool()) return true;
    QEventLoop loop;
    QTimer::singleShot(25, &loop, &QEventLoop::quit);
    loop.exec();
  }
  return false;
}

void SyncPage::loadKatex() {
  QFile file(katexDirectory() + "/katex.min.js");
  if (!file.open(QIODevice::ReadOnly)) return;
  run(QString::fromUtf8(file.readAll()));
}

bool SyncPage::printToPdf(const QString& path) {
  QEventLoop loop;
  bool ok = false;
  QObject::connect(page_.get(), &QWebEnginePage::pdfPrintingFinished, &loop,
                   [&](const QString&, bool success) {
                     ok = success;
                     loop.quit();
                   });
  page_->printToPdf(path,
                    QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait, QMarginsF(0, 0, 0, 0)));
  loop.exec();
  return ok;
}

}  // namespace rt::typeset
