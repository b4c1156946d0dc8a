#include "app/lesson_text_view.h"

#include <functional>
#include <memory>

#include <QChildEvent>
#include <QDesktopServices>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QKeyEvent>
#include <QPointer>
#include <QTimer>
#include <QUrl>
#include <QVBoxLayout>
#include <QWebEnginePage>
#include <QWebEngineView>

#include "lesson/markdown_html.h"
#include "lesson/maths.h"
#include "lesson/text_apparatus.h"
#include "typeset/web_engine.h"

namespace rt::app {
namespace {

// Links to a place on the page stay in the view; a link to another lesson ("form-factor.html#top", written
// beside the page) opens that lesson in the app; any other link opens in the reader's browser, never here.
class LessonPage : public QWebEnginePage {
 public:
  LessonPage(QObject* parent, std::function<void(const QString&)> openLesson)
      : QWebEnginePage(parent), openLesson_(std::move(openLesson)) {}

 protected:
  bool acceptNavigationRequest(const QUrl& url, NavigationType type, bool) override {
    if (type != NavigationTypeLinkClicked) return true;
    if (url.hasFragment() && url.adjusted(QUrl::RemoveFragment) == this->url().adjusted(QUrl::RemoveFragment))
      return true;
    const QUrl beside = this->url().adjusted(QUrl::RemoveFilename | QUrl::RemoveFragment);
    if (url.isLocalFile() && url.adjusted(QUrl::RemoveFilename | QUrl::RemoveFragment) == beside &&
        url.fileName().endsWith(".html")) {
      openLesson_(url.fileName().chopped(5));
      return false;
    }
    QDesktopServices::openUrl(url);
    return false;
  }

 private:
  std::function<void(const QString&)> openLesson_;
};

QString cssColour(const QColor& c) {
  return c.name(QColor::HexRgb);
}

// Text for a single-quoted JavaScript string.
QString scriptString(QString text) {
  return text.replace('\\', "\\\\").replace('\'', "\\'");
}

}  // namespace

LessonTextView::LessonTextView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  view_ = new QWebEngineView(this);
  view_->setPage(new LessonPage(view_, [this](const QString& id) { emit lessonLinkClicked(id); }));
  view_->setContextMenuPolicy(Qt::NoContextMenu);
  layout->addWidget(view_);
  setFocusProxy(view_);
  watchChildren(view_);
  connect(view_, &QWebEngineView::loadFinished, this, [this](bool) {
    loaded_ = true;
    applyStyle();
    const int generation = generation_;
    view_->page()->runJavaScript(typeset::typesetScript(), [this, generation](const QVariant& value) {
      // WebEngine calls back with no value when the page goes first (see ~LessonTextView).
      if (generation != generation_ || !value.isValid()) return;
      const QJsonObject o = QJsonDocument::fromJson(value.toString().toUtf8()).object();
      formulas_ = o.value("formulas").toInt();
      errors_.clear();
      for (const auto& e : o.value("errors").toArray()) errors_ << e.toString();
      typesetGeneration_ = generation;
      if (scrollToEnd_) view_->page()->runJavaScript("window.scrollTo(0, document.body.scrollHeight);");
      emit typeset(formulas_, errors_);
    });
  });
}

LessonTextView::~LessonTextView() {
  // WebEngine answers every pending script when its page is deleted. Deleted here, while this object's
  // members still exist, the answers find a newer generation and leave them alone; deleted later by
  // QWidget, with the children, they would write into members already destroyed.
  ++generation_;
  disconnect(view_, nullptr, this, nullptr);
  delete view_;
  view_ = nullptr;
}

void LessonTextView::setMarkdown(const QString& markdown, bool scrollToEnd) {
  markdown_ = markdown;
  scrollToEnd_ = scrollToEnd;
  loaded_ = false;
  ++generation_;
  const QString body = QString::fromStdString(lesson::markdownToHtml(markdown.toStdString()));
  view_->setHtml(pageHtml(body), QUrl::fromLocalFile(typeset::katexDirectory() + "/"));
}

QString LessonTextView::pageHtml(const QString& body) const {
  return "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">"
         "<link rel=\"stylesheet\" href=\"katex.min.css\"><script src=\"katex.min.js\"></script>"
         "<style id=\"look\">" +
         styleSheet() + "</style></head><body>\n" + body + "\n</body></html>\n";
}

int LessonTextView::textPixelSize() const {
  const QFontInfo info(font());
  return std::max(6, info.pixelSize());
}

QString LessonTextView::styleSheet() const {
  // The widget's font and palette, so that presenter mode (larger, white on black) and the zoom keys reach
  // the page; KaTeX sizes its maths relative to the text around it.
  const QPalette& p = palette();
  return QString(
             "body { font-family: '%1', 'DejaVu Sans', sans-serif; font-size: %2px; line-height: 1.45; "
             "color: %3; background: %4; margin: 6px 10px; }"
             "a { color: %5; } h1 { font-size: 1.45em; } h2 { font-size: 1.25em; }"
             "pre, code { font-family: 'DejaVu Sans Mono', monospace; font-size: 0.95em; }"
             "pre { white-space: pre-wrap; } .katex-display { overflow-x: auto; overflow-y: hidden; "
             "padding: 0.1em 0; } .katex-error { color: #d00; } table { border-collapse: collapse; }"
             "th, td { border: 1px solid %6; padding: 0.15em 0.5em; }"
             // A blockquote is a boxed note (docs/lesson-format.md), as in the HTML book and the PDF.
             "blockquote { border: 1px solid %6; border-left-width: 4px; border-radius: 3px; "
             "margin: 0.8em 0; padding: 0.2em 0.8em; background: %7; }")
             .arg(font().family())
             .arg(textPixelSize())
             .arg(cssColour(p.color(QPalette::Text)), cssColour(p.color(QPalette::Base)),
                  cssColour(p.color(QPalette::Link)), cssColour(p.color(QPalette::Mid)))
             .arg(cssColour(p.color(QPalette::AlternateBase))) +
         QString::fromStdString(lesson::apparatusStyleSheet() + lesson::equationStyleSheet()).simplified();
}

void LessonTextView::applyStyle() {
  view_->page()->setBackgroundColor(palette().color(QPalette::Base));
  if (!loaded_) return;
  // A page replaced while it loaded reports its end all the same (not ok): the new one may not have its
  // style element yet, and takes the style it was written with.
  view_->page()->runJavaScript("var look = document.getElementById('look'); if (look) look.textContent = '" +
                               scriptString(styleSheet()) + "';");
}

void LessonTextView::changeEvent(QEvent* event) {
  if (event->type() == QEvent::FontChange || event->type() == QEvent::PaletteChange) applyStyle();
  QWidget::changeEvent(event);
}

QWidget* LessonTextView::viewport() const {
  return view_->focusProxy() ? view_->focusProxy() : view_;
}

void LessonTextView::watchChildren(QObject* object) {
  object->installEventFilter(this);
  for (QObject* child : object->children())
    if (child->isWidgetType()) watchChildren(child);
}

bool LessonTextView::eventFilter(QObject* watched, QEvent* event) {
  // WebEngine makes its own widget for the page later: it must pass the navigation keys on too.
  if (event->type() == QEvent::ChildAdded) {
    QObject* child = static_cast<QChildEvent*>(event)->child();
    if (child->isWidgetType()) watchChildren(child);
  }
  if (event->type() == QEvent::ShortcutOverride) {
    auto* key = static_cast<QKeyEvent*>(event);
    const bool navigation = key->key() == Qt::Key_Left || key->key() == Qt::Key_Right ||
                            key->key() == Qt::Key_PageUp || key->key() == Qt::Key_PageDown ||
                            key->key() == Qt::Key_Space;
    if (navigation && key->modifiers() == Qt::NoModifier) {
      event->ignore();  // the window's step shortcuts run, not the page's scrolling
      return true;
    }
  }
  return QWidget::eventFilter(watched, event);
}

bool LessonTextView::waitUntilShown(int timeoutMs) {
  QElapsedTimer clock;
  clock.start();
  auto wait = [](int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
  };
  while (typesetGeneration_ != generation_ && clock.elapsed() < timeoutMs) wait(20);
  if (typesetGeneration_ != generation_) return false;
  wait(250);  // Chromium composites the typeset page in its own time
  return true;
}

QJsonObject LessonTextView::pageAnswer(const QString& script, int timeoutMs) {
  // The page answers on its own thread's time: wait for it, but never longer than the caller allows.
  // An answer that comes after the timeout finds the loop gone and is dropped: it must not write into this
  // frame, which has returned by then.
  QEventLoop loop;
  const QPointer<QEventLoop> waiting(&loop);
  auto answer = std::make_shared<QVariant>();
  view_->page()->runJavaScript(script, [waiting, answer](const QVariant& value) {
    if (!waiting) return;
    *answer = value;
    waiting->quit();
  });
  QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
  loop.exec();
  return QJsonDocument::fromJson(answer->toString().toUtf8()).object();
}

LessonTextView::MathsState LessonTextView::mathsState(int timeoutMs) {
  MathsState state;
  if (!waitUntilShown(timeoutMs)) return state;
  const QJsonObject o = pageAnswer(
      "(function () { var eq = Array.prototype.map.call(document.querySelectorAll('.katex'), function (e) {"
      " return parseFloat(getComputedStyle(e).fontSize); });"
      " var overlaps = 0; document.querySelectorAll('.katex-display').forEach(function (d) {"
      "  var tag = d.querySelector('.tag'); if (!tag) return; var t = tag.getBoundingClientRect();"
      "  d.querySelectorAll('.katex-html > .base').forEach(function (b) { var r = b.getBoundingClientRect();"
      "   if (r.right > t.left + 0.5 && r.left < t.right - 0.5 && r.bottom > t.top && r.top < t.bottom)"
      "    overlaps++; }); });"
      " return JSON.stringify({katex: eq.length, body: parseFloat(getComputedStyle(document.body).fontSize),"
      " smallest: eq.length ? Math.min.apply(null, eq) : 0, overlaps: overlaps}); })()",
      timeoutMs);
  state.ready = !o.isEmpty();
  state.formulas = formulas_;
  state.errors = errors_;
  state.katexNodes = o.value("katex").toInt();
  state.bodyPixels = o.value("body").toDouble();
  state.smallestEquationPixels = o.value("smallest").toDouble();
  state.numbersOverEquations = o.value("overlaps").toInt();
  return state;
}

QRect LessonTextView::linkRect(const QString& hrefSuffix, int timeoutMs) {
  if (!waitUntilShown(timeoutMs)) return {};
  return pageRect(
      "Array.prototype.find.call(document.querySelectorAll('a[href]'), function (e) {"
      " return e.getAttribute('href').endsWith('" +
          scriptString(hrefSuffix) + "'); })",
      true, timeoutMs);
}

QRect LessonTextView::elementRect(const QString& id, int timeoutMs) {
  if (!waitUntilShown(timeoutMs)) return {};
  return pageRect("document.getElementById('" + scriptString(id) + "')", false, timeoutMs);
}

QRect LessonTextView::pageRect(const QString& element, bool scrollIntoView, int timeoutMs) {
  const QJsonObject o =
      pageAnswer("(function () { var a = " + element + "; if (!a) return '';" +
                     (scrollIntoView ? " a.scrollIntoView({block: 'center'});" : "") +
                     " var r = a.getBoundingClientRect();"
                     " return JSON.stringify({x: r.left, y: r.top, w: r.width, h: r.height}); })()",
                 timeoutMs);
  if (o.isEmpty()) return {};
  const double zoom = view_->zoomFactor();
  return QRectF(o.value("x").toDouble() * zoom, o.value("y").toDouble() * zoom,
                o.value("w").toDouble() * zoom, o.value("h").toDouble() * zoom)
      .toAlignedRect();
}

}  // namespace rt::app
