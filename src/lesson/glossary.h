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
