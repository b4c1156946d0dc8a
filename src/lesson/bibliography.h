// The book's bibliography: one CSL-JSON file beside the lessons (lessons/references.json), the format that
// citation processors and reference managers read and write. Each entry is formatted here, author-year: the
// label a citation shows ("Goral et al. 1984"), the full entry for a reference list (HTML) and for a
// tooltip (plain text). Only the CSL fields the book uses are read; an entry without an id, a title, an
// author (or editor) or a year is an InputError naming the file and the entry's JSON path.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rt::lesson {

struct Person {
  std::string family, given;
};

struct Reference {
  std::string key;   // CSL "id", what a lesson cites: [@key]
  std::string type;  // CSL type: article-journal, paper-conference, book, chapter, thesis, report
  std::vector<Person> authors;
  std::vector<Person> editors;
  int year = 0;
  std::string title, container, collection, number, publisher, place, volume, issue, pages, edition, genre,
      doi, url, note;
  std::string label;  // "Goral et al. 1984"; a letter follows the year where two entries would read alike
};

struct Bibliography {
  std::string file;  // where it was read from; empty when there is none
  std::vector<Reference> entries;
  const Reference* find(const std::string& key) const;
};

// The bibliography of the lessons in `lessonsDir`: its references.json, or an empty one when there is none.
std::string bibliographyPath(const std::string& lessonsDir);
Bibliography loadBibliography(const std::string& path);
// Parses CSL-JSON text; `file` names it in errors.
Bibliography parseBibliography(const std::string& json, const std::string& file);

// The full entry: HTML (titles of books and venues in italics) and plain text.
std::string entryHtml(const Reference& r);
std::string entryText(const Reference& r);

// The entries with these keys (unknown keys skipped), sorted as a reference list is: by the first author's
// family name, then year, then label.
std::vector<const Reference*> sortedEntries(const Bibliography& bibliography,
                                            const std::vector<std::string>& keys);
// A reference list: one HTML block (which Markdown passes through) of paragraphs with the anchor ids
// "ref-<key>" that citations link to.
std::string referenceListHtml(const std::vector<const Reference*>& entries);

}  // namespace rt::lesson
