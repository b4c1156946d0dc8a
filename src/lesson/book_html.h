// The book as HTML: one page per lesson, an index with the table of contents, and one printable document of
// the whole book (title page, contents, chapters) for the PDF. Sections are numbered <chapter>.<k>, figures
// "Figure <chapter>.<k>", and chapters by the lessons' order. Maths stays as <x-equation> elements, for the
// typesetter (src/typeset) to set; every path is relative, so the site opens from the file system.
#pragma once

#include <string>
#include <vector>

#include "lesson/book.h"

namespace rt::lesson {

// The file names of the site. KaTeX's style sheet and fonts are copied to katex/ beside the pages.
inline constexpr const char* kBookStyleFile = "book.css";
inline constexpr const char* kBookIndexFile = "index.html";
inline constexpr const char* kBookPrintFile = "book-print.html";
std::string lessonPageFile(const RenderedLesson& lesson);  // "<id>.html"

// The book's title, as the index and the title page show it.
std::string bookTitle();

// A lesson's page; `lessons` (in order) gives the chapter navigation. The steps' text is Markdown whose maths
// prepareMaths() has numbered.
std::string lessonPageHtml(const RenderedLesson& lesson, const std::vector<RenderedLesson>& lessons);
// `withPdf`: the index links to book.pdf beside it.
std::string indexPageHtml(const std::vector<RenderedLesson>& lessons, bool withPdf = true);
// The whole book in one document: a title page, the contents (page numbers filled in when it is laid out
// into pages) and every chapter. Its blocks are the children of <div id="flow">, for the page layout.
std::string printBookHtml(const std::vector<RenderedLesson>& lessons);
// Any Markdown document (a homework handout, an answer key) in the printed book's form, for the same
// typesetter: A4 pages, the book's style inline, KaTeX's style sheet from `katexStyleUrl` (a file URL, so
// that nothing has to be copied beside the document). Relative paths in the Markdown (figures) are relative
// to where the HTML is written.
// `dense`: smaller type and margins, for a long reference document such as a class's answer key.
std::string printDocumentHtml(const std::string& title, const std::string& markdown,
                              const std::string& katexStyleUrl, bool dense = false);
// The style sheet shared by the pages and the printed book.
std::string bookStyleSheet();

}  // namespace rt::lesson
