// The book's glossary: lessons/glossary.json, a list of {"term", "definition"} (definitions may hold maths in
// $...$). Each term is defined once, in the Glossary chapter, which links every term to the section of the
// book where it is first used. An entry {"term", "index-only": true} has no definition: it is a term of the
// book's index only (lesson/book_index.h).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lesson/lesson.h"

namespace rt::lesson {

struct GlossaryEntry {
  std::string term, definition;
  bool indexOnly = false;  // in the index, not defined in the glossary
};

// The glossary of the lessons in `lessonsDir`; empty when it has none. InputError naming the file and the
// entry's JSON path on a malformed entry or a term defined twice.
std::string glossaryPath(const std::string& lessonsDir);
std::vector<GlossaryEntry> loadGlossary(const std::string& path);

// Every use of the term in a Markdown text, as [begin, end) offsets in reading order: in normal text (not
// code, not maths, not a link's text), as a whole word, in any case, plural or not.
std::vector<std::pair<std::size_t, std::size_t>> termUses(const std::string& markdown,
                                                          const std::string& term);
// The anchor of a term's definition in the Glossary chapter: "gl-form-factor".
std::string glossaryAnchor(const std::string& term);

// A term's definition as plain text (maths as Unicode), for a link's title: what hovering over the term
// shows.
std::string definitionText(const GlossaryEntry& entry);

// The first use of each term in a Markdown text (as termUses finds them), longer terms first, so that
// "delta form factor" takes its words before "form factor" looks for a use of its own: at most one range per
// term, none overlapping, in the order longer terms first.
struct TermUse {
  const GlossaryEntry* entry = nullptr;
  std::pair<std::size_t, std::size_t> range;
};
std::vector<TermUse> firstTermUses(const std::string& markdown, const std::vector<GlossaryEntry>& entries);

// A page that stands on its own (the app's text pane shows one step of a lesson): the first use of each
// defined term on it becomes a link to its definition on the same page ("#gl-<term>", the definition as the
// link's title, which shows on hover). `linked` holds the terms the page links already, in an earlier text
// of it: they are not linked again; those linked here are added in the order of the text.
std::string linkTermsToDefinitions(const std::string& markdown, const std::vector<GlossaryEntry>& entries,
                                   std::vector<const GlossaryEntry*>& linked);
// The definitions for such a page, under a heading of level `level` ("Terms"): one paragraph per term,
// anchored "gl-<term>" as in the Glossary chapter. Empty when there are none.
std::string termDefinitionsHtml(const std::vector<const GlossaryEntry*>& terms, int level);

// Where a term is first used in the lessons (given in book order): in a title or in normal text (not code,
// not maths), as a whole word, in any case, plural or not.
struct FirstUse {
  const Lesson* lesson = nullptr;
  int section = 0;  // 0: the introduction; k: the k-th step
};
std::optional<FirstUse> firstUse(const std::string& term, const std::vector<Lesson>& lessons);
// The answer points into `lessons`, so they must outlive it.
std::optional<FirstUse> firstUse(const std::string& term, std::vector<Lesson>&& lessons) = delete;

// The Glossary chapter's body (index-only entries left out): one paragraph per term (anchor "gl-<term>",
// alphabetical), each ending with a link to its first use: "<lesson id>.html#s<order>-<k>", or "#top" for an
// introduction.
std::string glossaryHtml(const std::vector<GlossaryEntry>& entries, const std::vector<Lesson>& lessons);

}  // namespace rt::lesson
