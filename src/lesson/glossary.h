// The book's glossary: lessons/glossary.json, a list of {"term", "definition"} (definitions may hold maths in
// $...$). Each term is defined once, in the Glossary chapter, which links every term to the section of the
// book where it is first used.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lesson/lesson.h"

namespace rt::lesson {

struct GlossaryEntry {
  std::string term, definition;
};

// The glossary of the lessons in `lessonsDir`; empty when it has none. InputError naming the file and the
// entry's JSON path on a malformed entry or a term defined twice.
std::string glossaryPath(const std::string& lessonsDir);
std::vector<GlossaryEntry> loadGlossary(const std::string& path);

// Where a term is first used in the lessons (given in book order): in a title or in normal text (not code,
// not maths), as a whole word, in any case, plural or not.
struct FirstUse {
  const Lesson* lesson = nullptr;
  int section = 0;  // 0: the introduction; k: the k-th step
};
std::optional<FirstUse> firstUse(const std::string& term, const std::vector<Lesson>& lessons);
// The answer points into `lessons`, so they must outlive it.
std::optional<FirstUse> firstUse(const std::string& term, std::vector<Lesson>&& lessons) = delete;

// The Glossary chapter's body: one paragraph per term (anchor "gl-<term>", alphabetical), each ending with a
// link to its first use: "<lesson id>.html#s<order>-<k>", or "#top" for an introduction.
std::string glossaryHtml(const std::vector<GlossaryEntry>& entries, const std::vector<Lesson>& lessons);

}  // namespace rt::lesson
