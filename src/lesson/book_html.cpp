#include "lesson/book_html.h"

#include <algorithm>

#include "lesson/book_index.h"
#include "lesson/markdown_html.h"
#include "lesson/maths.h"
#include "lesson/text_apparatus.h"

namespace rt::lesson {
namespace {

std::string number(const RenderedLesson& l) {
  return std::to_string(l.order);
}

std::string head(const std::string& title, const std::string& extra = "") {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
         escapeHtml(title) +
         "</title>\n<link rel=\"stylesheet\" href=\"katex/katex.min.css\">\n<link rel=\"stylesheet\" "
         "href=\"" +
         kBookStyleFile + "\">\n" + extra + "</head>\n";
}

std::string sectionId(const RenderedLesson& l, std::size_t k) {
  return "s" + number(l) + "-" + std::to_string(k + 1);
}

// The chapter's body: headings, figures with numbered captions, and the text. `idPrefix` keeps the anchors of
// different chapters apart in the one printed document.
std::string chapterBody(const RenderedLesson& l, const std::string& idPrefix, bool forPrint) {
  std::string html = "<h1 class=\"chapter\" id=\"" + idPrefix +
                     "top\"><span class=\"chapter-number\">Chapter " + number(l) + "</span> " +
                     escapeHtml(l.title) + "</h1>\n";
  if (!l.summary.empty()) html += "<p class=\"summary\">" + escapeHtml(l.summary) + "</p>\n";
  if (!l.intro.empty()) html += markdownToHtml(l.intro);
  int figure = 0;
  for (std::size_t k = 0; k < l.steps.size(); ++k) {
    const RenderedStep& step = l.steps[k];
    const std::string id = idPrefix + sectionId(l, k);
    html += "<h2 id=\"" + id + "\"><span class=\"section-number\">" + number(l) + "." +
            std::to_string(k + 1) + "</span> " + escapeHtml(step.title) + "</h2>\n";
    for (const RenderedFigure& f : step.figures) {
      const std::string label = "Figure " + number(l) + "." + std::to_string(++figure);
      html += "<figure id=\"" + idPrefix + "fig" + number(l) + "-" + std::to_string(figure) +
              "\"><img src=\"" + escapeHtml(f.file) + "\" alt=\"" + escapeHtml(f.caption) +
              "\"><figcaption><b>" + label + ".</b> " + escapeHtml(f.caption) + "</figcaption></figure>\n";
    }
    html += markdownToHtml(step.text);
  }
  if (!l.furtherReading.empty())
    html += "<h2 class=\"further-reading\" id=\"" + idPrefix + "further-reading\">Further reading</h2>\n" +
            l.furtherReading;
  // Links to equations, listings, cited works, marked terms and definitions point into a chapter; in the
  // printed document every chapter has its own prefix.
  if (forPrint) {
    for (const std::string kind : {"eq-", "alg-", "ref-", "ix-", "gl-"}) {
      for (std::size_t at = 0; (at = html.find("href=\"#" + kind, at)) != std::string::npos; at += 7)
        html.insert(at + 7, idPrefix);
      for (std::size_t at = 0; (at = html.find("id=\"" + kind, at)) != std::string::npos; at += 4)
        html.insert(at + 4, idPrefix);
    }
  }
  return html;
}

std::string navigation(const RenderedLesson& l, const std::vector<RenderedLesson>& lessons) {
  const auto at = std::find_if(lessons.begin(), lessons.end(), [&](const auto& x) { return x.id == l.id; });
  std::string html = "<nav class=\"chapters\">";
  if (at != lessons.end() && at != lessons.begin()) {
    const auto& p = *(at - 1);
    html += "<a rel=\"prev\" href=\"" + lessonPageFile(p) + "\">&larr; " + number(p) + ". " +
            escapeHtml(p.title) + "</a>";
  }
  html += " <a href=\"index.html\">Contents</a> ";
  if (at != lessons.end() && at + 1 != lessons.end()) {
    const auto& n = *(at + 1);
    html += "<a rel=\"next\" href=\"" + lessonPageFile(n) + "\">" + number(n) + ". " + escapeHtml(n.title) +
            " &rarr;</a>";
  }
  return html + "</nav>\n";
}

// The contents: chapters grouped by part, each with its sections. `href` gives a chapter's link target.
template <typename Href>
std::string contents(const std::vector<RenderedLesson>& lessons, Href href, bool pageNumbers) {
  std::string html;
  std::string part;
  for (const auto& l : lessons) {
    if (!l.chapter.empty() && l.chapter != part) {
      part = l.chapter;
      html += "<div class=\"toc-part\">" + escapeHtml(part) + "</div>\n";
    }
    const std::string page = pageNumbers ? "<span class=\"toc-page\"></span>" : "";
    html += "<div class=\"toc-chapter\"><a href=\"" + href(l, std::string("top")) + "\">" + number(l) + ". " +
            escapeHtml(l.title) + "</a>" + page + "</div>\n";
    for (std::size_t k = 0; k < l.steps.size(); ++k)
      html += "<div class=\"toc-section\"><a href=\"" + href(l, sectionId(l, k)) + "\">" + number(l) + "." +
              std::to_string(k + 1) + " " + escapeHtml(l.steps[k].title) + "</a>" + page + "</div>\n";
  }
  return html;
}

}  // namespace

std::string lessonPageFile(const RenderedLesson& lesson) {
  return lesson.id + ".html";
}

std::string bookTitle() {
  return "The Radiosity Method, Step by Step";
}

std::string lessonPageHtml(const RenderedLesson& lesson, const std::vector<RenderedLesson>& lessons) {
  std::string html = head(number(lesson) + ". " + lesson.title + " - " + bookTitle());
  html +=
      "<body>\n" + navigation(lesson, lessons) + "<main>\n" + chapterBody(lesson, "", false) + "</main>\n";
  html += navigation(lesson, lessons) + "</body>\n</html>\n";
  return html;
}

std::string indexPageHtml(const std::vector<RenderedLesson>& lessons, bool withPdf) {
  std::string html = head(bookTitle());
  html += "<body>\n<main>\n<h1 class=\"book-title\">" + escapeHtml(bookTitle()) + "</h1>\n";
  html +=
      "<p class=\"summary\">An interactive textbook of the radiosity method. Every number in the text and "
      "every figure was computed when this book was built.";
  if (withPdf) html += " The whole book is also one PDF: <a href=\"book.pdf\">book.pdf</a>.";
  html += "</p>\n<h2>Contents</h2>\n<div class=\"toc\">\n";
  html += contents(
      lessons,
      [](const RenderedLesson& l, const std::string& anchor) { return lessonPageFile(l) + "#" + anchor; },
      false);
  html += "</div>\n</main>\n</body>\n</html>\n";
  return html;
}

std::string printBookHtml(const std::vector<RenderedLesson>& lessons) {
  std::string html = head(bookTitle(), "<style>@page { size: A4; margin: 0; }</style>\n");
  html += "<body class=\"print\">\n<div id=\"flow\">\n";
  html += "<div class=\"title-page\"><h1 class=\"book-title\">" + escapeHtml(bookTitle()) +
          "</h1><p class=\"subtitle\">An interactive textbook of the radiosity method</p>"
          "<p class=\"subtitle\">" +
          std::to_string(lessons.size()) + " chapters, computed and typeset by radiosity book</p></div>\n";
  html += "<h1 class=\"toc-title\">Contents</h1>\n";
  html += contents(
      lessons,
      [](const RenderedLesson& l, const std::string& anchor) { return "#c" + number(l) + "-" + anchor; },
      true);
  for (const auto& l : lessons) html += chapterBody(l, "c" + number(l) + "-", true);
  html += "</div>\n</body>\n</html>\n";
  // Links between chapters ("hemicube.html#s5-2", from the glossary) point into the one document.
  for (const auto& l : lessons) {
    const std::string from = "href=\"" + lessonPageFile(l) + "#", to = "href=\"#c" + number(l) + "-";
    for (std::size_t at = 0; (at = html.find(from, at)) != std::string::npos; at += to.size())
      html.replace(at, from.size(), to);
  }
  return html;
}

std::string printDocumentHtml(const std::string& title, const std::string& markdown,
                              const std::string& katexStyleUrl, bool dense) {
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                     escapeHtml(title) + "</title>\n<link rel=\"stylesheet\" href=\"" +
                     escapeHtml(katexStyleUrl) + "\">\n<style>\n" + bookStyleSheet() +
                     "@page { size: A4; margin: 0; }\n</style>\n</head>\n";
  // The page layout moves the children of #flow into pages, so the document's blocks must be its children.
  return html + "<body class=\"print document" + (dense ? " dense" : "") + "\">\n<div id=\"flow\">\n" +
         markdownToHtml(markdown) + "</div>\n</body>\n</html>\n";
}

std::string bookStyleSheet() {
  return R"(/* The book's pages and its printed form. */
body { font-family: "DejaVu Serif", Georgia, serif; font-size: 17px; line-height: 1.5; color: #111;
       background: #fff; margin: 0; }
main { max-width: 46em; margin: 0 auto; padding: 1em 1.5em 3em; }
h1, h2, h3, nav, figcaption, .toc-part { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; }
h1 { font-size: 1.9em; margin: 0.8em 0 0.3em; }
h1 .chapter-number { display: block; font-size: 0.55em; font-weight: normal; color: #555; }
h2 { font-size: 1.35em; margin: 1.4em 0 0.4em; }
.section-number { color: #555; margin-right: 0.3em; }
.summary { font-style: italic; color: #333; }
nav.chapters { display: flex; justify-content: space-between; gap: 1em; padding: 0.6em 1.5em;
               background: #f2f2f2; font-size: 0.9em; }
figure { margin: 1.2em 0; text-align: center; break-inside: avoid; }
figure img { max-width: 100%; max-height: 70vh; }
figcaption { font-size: 0.9em; color: #333; margin-top: 0.3em; }
pre, code { font-family: "DejaVu Sans Mono", monospace; font-size: 0.9em; }
pre { background: #f5f5f5; padding: 0.6em; overflow-x: auto; }
table { border-collapse: collapse; margin: 1em 0; }
th, td { border: 1px solid #bbb; padding: 0.2em 0.6em; }
.katex-display { margin: 0.8em 0; overflow-x: auto; overflow-y: hidden; }
.katex-error { color: #b00; }
/* A blockquote is a boxed note (docs/lesson-format.md): a note for readers of the course slides, for one. */
blockquote { border: 1px solid #999; border-left: 4px solid #777; border-radius: 3px; background: #f6f6f1;
             margin: 1em 0; padding: 0.2em 0.9em; break-inside: avoid; }
a { color: #0645ad; }
.toc-part { font-weight: bold; margin-top: 0.9em; }
.toc-chapter { margin-left: 1em; font-weight: bold; display: flex; }
.toc-section { margin-left: 2.5em; display: flex; }
.toc-chapter a, .toc-section a { flex: 1; text-decoration: none; color: inherit; }
.toc-page { min-width: 2.5em; text-align: right; }
/* The printed book: pages laid out by the typesetter, A4 with a page number at the foot. Each page is its own
   layout (contain): the layout carries blocks between pages and measures one page at a time. */
body.print { font-size: 11pt; }
.print .page { width: 210mm; height: 296.8mm; position: relative; overflow: hidden; box-sizing: border-box;
               padding: 20mm 22mm 24mm; break-after: page; contain: strict; }
.print .page-body { height: 100%; overflow: hidden; }
.print .page-body > :first-child { margin-top: 0; }  /* a page's top edge is its first block's space */
.print .page-number { position: absolute; bottom: 12mm; left: 0; right: 0; text-align: center;
                      font-family: "DejaVu Sans", sans-serif; font-size: 9pt; color: #333; }
.print figure img { max-height: 110mm; max-width: 100%; }
.print .title-page { text-align: center; padding-top: 70mm; }
.print.dense { font-size: 9pt; line-height: 1.35; }
.print.dense .page { padding: 14mm 16mm 18mm; }
.print .book-title { font-size: 2.4em; }
.print .subtitle { font-size: 1.2em; color: #444; }
)" + apparatusStyleSheet() +
         equationStyleSheet() + indexStyleSheet();
}

}  // namespace rt::lesson
