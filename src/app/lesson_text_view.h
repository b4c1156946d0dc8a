// The step's text pane: the lesson's Markdown as HTML (md4c) in a web view, its maths typeset by KaTeX from
// the local libjs-katex (nothing is fetched from the network). The page follows the widget's font and
// palette, so presenter mode and the zoom keys scale the equations with the text.
#pragma once

#include <QJsonObject>
#include <QPalette>
#include <QRect>
#include <QString>
#include <QStringList>
#include <QWidget>

class QWebEngineView;

namespace rt::app {

class LessonTextView : public QWidget {
  Q_OBJECT

 public:
  explicit LessonTextView(QWidget* parent = nullptr);
  ~LessonTextView() override;

  // Shows Markdown whose maths is ready (lesson::prepareMaths: numbered equations, linked references).
  // `scrollToEnd`: once typeset, the page shows its end (what was just added under the text).
  void setMarkdown(const QString& markdown, bool scrollToEnd = false);
  // The text shown, as Markdown (the words a reader sees, for tests and for copying).
  QString toPlainText() const { return markdown_; }
  // The size of the body text on the page, in CSS pixels (from the widget's font).
  int textPixelSize() const;
  // The widget that takes the mouse and the keys (WebEngine's own, once the page exists; else the view).
  QWidget* viewport() const;

  // What the page shows once its maths is typeset: waits (up to timeoutMs) for the page to be ready.
  struct MathsState {
    bool ready = false;
    int formulas = 0;       // <x-equation> elements the page had
    int katexNodes = 0;     // elements KaTeX produced (.katex)
    QStringList errors;     // KaTeX's messages for formulas that failed
    double bodyPixels = 0;  // computed font sizes on the page
    double smallestEquationPixels = 0;
    int numbersOverEquations = 0;  // displayed equations whose number's box meets the equation's
  };
  MathsState mathsState(int timeoutMs = 15000);
  // Where the first link whose target ends with `hrefSuffix` is, in viewport() coordinates, once scrolled
  // into view (waits for the page like mathsState); empty when the page has no such link.
  QRect linkRect(const QString& hrefSuffix, int timeoutMs = 15000);
  // Where the element with this id (a definition "gl-<term>", a reference "ref-<key>") is, in viewport()
  // coordinates as the page is scrolled now (waits for the page like mathsState); empty when it has none.
  QRect elementRect(const QString& id, int timeoutMs = 15000);
  // Waits until the page of the last setMarkdown is typeset and has had time to be drawn (screenshots).
  bool waitUntilShown(int timeoutMs = 15000);

 signals:
  // The page of the last setMarkdown is shown and its maths set.
  void typeset(int formulas, const QStringList& errors);
  // A reference to another lesson (lesson::prepareLessonReferences) was clicked.
  void lessonLinkClicked(const QString& id);

 protected:
  void changeEvent(QEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  QString pageHtml(const QString& body) const;
  // Runs a script that returns JSON text on the page; its answer (empty when none came in time).
  QJsonObject pageAnswer(const QString& script, int timeoutMs);
  // The rectangle of the element a script expression gives, in viewport() coordinates; empty when none.
  QRect pageRect(const QString& element, bool scrollIntoView, int timeoutMs);
  QString styleSheet() const;
  void applyStyle();
  void watchChildren(QObject* object);

  QWebEngineView* view_ = nullptr;
  QString markdown_;
  bool loaded_ = false;
  bool scrollToEnd_ = false;
  int generation_ = 0;  // of the page shown, so that a late answer for an older page is ignored
  int typesetGeneration_ = -1;
  int formulas_ = 0;
  QStringList errors_;
};

}  // namespace rt::app
