// The book's index: every term of lessons/glossary.json (its defined terms and its index-only ones) with each
// section of the book whose text uses it. The first use of a term in a section is marked with an anchor the
// index links to, so that a link lands on the word itself (and, in the PDF, its page number is the page the
// word is on); the first use in a chapter of a defined term is also a link to its definition in the Glossary
// chapter. Uses are found as the glossary finds them (lesson::termUses): whole words in normal text.
#pragma once

#include <string>
#include <vector>

#include "lesson/book.h"
#include "lesson/glossary.h"

namespace rt::lesson {

struct IndexLocator {
  std::string page;    // the chapter's page, "<id>.html"
  std::string anchor;  // the marked use: "ix-<term>-<chapter>-<section>"
  std::string label;   // the chapter's number for its introduction ("6"), else the section's ("6.2")
};

struct IndexEntry {
  std::string term;
  bool defined = false;                // has a definition in the Glossary chapter
  std::vector<IndexLocator> locators;  // in book order
};

inline constexpr const char* kGlossaryPage = "glossary.html";

// Marks the uses of the terms in the chapters' prepared text (introductions and steps, Markdown as
// prepareText leaves it) and returns the index, sorted by term, leaving out terms the chapters never use.
// Where two terms overlap ("delta form factor", "form factor") the longer one is marked.
std::vector<IndexEntry> markIndexTerms(std::vector<RenderedLesson>& chapters,
                                       const std::vector<GlossaryEntry>& terms);

// The Index chapter's body: one paragraph per term (class "index-entry"), the term (a link to its definition
// when it has one) followed by one link per locator (class "index-ref"). The printed book replaces each
// link's text by the page number of its target and drops repeated pages.
std::string indexHtml(const std::vector<IndexEntry>& index);

// The style of marked uses and of the index, shared by the book's pages and the printed book.
std::string indexStyleSheet();

}  // namespace rt::lesson
