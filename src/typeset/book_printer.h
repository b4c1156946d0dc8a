// The printed book: the one-document HTML of the whole book (lesson::printBookHtml) with its maths set, laid
// out into numbered A4 pages (chapters start a page, headings stay with what follows, the contents get their
// page numbers) and printed to PDF by WebEngine, text and vector figures as vectors.
#pragma once

#include <QString>
#include <string>
#include <vector>

#include "typeset/typesetter.h"

namespace rt::typeset {

struct PrintedBook {
  int pages = 0;
  MathsReport maths;
  std::vector<std::string> tooWide;  // displayed equations wider than the text: "page N: <TeX>"
};

// Also prints any document written by lesson::printDocumentHtml (handouts, answer keys). The PDF is readable
// by all, as a document to hand out.
// Throws std::runtime_error when the document cannot be loaded or the PDF cannot be written.
PrintedBook printBook(const QString& htmlFile, const QString& pdfFile);

}  // namespace rt::typeset
