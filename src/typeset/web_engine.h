// Qt WebEngine as a typesetting engine: the settings it needs before the application object exists, the
// KaTeX files it loads, and a page that runs scripts synchronously (for programs without an event loop of
// their own, such as the command line).
#pragma once

#include <QString>
#include <QVariant>
#include <functional>
#include <memory>

class QGuiApplication;
class QWebEnginePage;

namespace rt::typeset {

// Call before the QApplication is made: WebEngine shares OpenGL contexts with the widgets, and, run as root
// (a container, a build machine), Chromium's sandbox cannot start and must be turned off.
void prepareWebEngine();

// Call after the last web view is deleted and before the QApplication goes (the window closed, a test's
// window gone): a deleted view leaves parts of itself to deleteLater, and WebEngine must delete them while
// its profile and the application still exist. Left to the application's destructor, they were deleted
// after Chromium's teardown and corrupted the heap at exit.
void releaseDeletedWebViews();

// KaTeX's folder (katex.min.js, katex.min.css, fonts/): $RT_KATEX_DIR, or the one found when building.
QString katexDirectory();
// The script that replaces every <x-equation> element of the page by KaTeX's rendering. It returns (and
// leaves in window.rtMaths) a JSON object {"formulas": N, "errors": ["message", ...]}; a formula that fails
// is shown as its TeX in red (class katex-error) and its error is listed.
QString typesetScript();

// Makes a QGuiApplication when there is none (the command line), with the offscreen platform when there is
// no display, and WebEngine prepared. Keep it alive while pages are used.
class WebSession {
 public:
  WebSession();
  ~WebSession();
  WebSession(const WebSession&) = delete;
  WebSession& operator=(const WebSession&) = delete;

 private:
  std::unique_ptr<QGuiApplication> app_;
};

// A page used without a view, whose loads and scripts wait for their result.
class SyncPage {
 public:
  SyncPage();
  ~SyncPage();
  // Loads the HTML (with baseUrl for its relative paths) or a file; false when loading failed.
  bool setHtml(const QString& html, const QUrl& baseUrl);
  bool load(const QUrl& url);
  QVariant run(const QString& script);
  // Runs `condition` (a script returning true or false) until it is true or `timeoutMs` passed.
  bool waitFor(const QString& condition, int timeoutMs);
  // Loads KaTeX's script into the page (for a page that does not include it).
  void loadKatex();
  bool printToPdf(const QString& path);
  QWebEnginePage& page() { return *page_; }

 private:
  bool waitForLoad();
  std::unique_ptr<QWebEnginePage> page_;
  bool loaded_ = false, ok_ = false;
};

}  // namespace rt::typeset
