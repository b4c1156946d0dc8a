#include "lesson/bibliography.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "lesson/markdown_html.h"

namespace rt::lesson {
namespace {

using nlohmann::json;

// A CSL field that may be written as a string or a number ("volume": 18 or "18").
std::string text(const json& entry, const char* field) {
  const auto it = entry.find(field);
  if (it == entry.end() || it->is_null()) return {};
  if (it->is_string()) return it->get<std::string>();
  if (it->is_number_integer()) return std::to_string(it->get<long long>());
  return it->dump();
}

// The CSL fields read as they are, and where they go.
const std::pair<const char*, std::string Reference::*> kTextFields[] = {
    {"container-title", &Reference::container},
    {"collection-title", &Reference::collection},
    {"number", &Reference::number},
    {"publisher", &Reference::publisher},
    {"publisher-place", &Reference::place},
    {"volume", &Reference::volume},
    {"issue", &Reference::issue},
    {"page", &Reference::pages},
    {"edition", &Reference::edition},
    {"genre", &Reference::genre},
    {"DOI", &Reference::doi},
    {"URL", &Reference::url},
    {"note", &Reference::note}};

std::vector<Person> people(const json& entry, const char* field, const SourceLocation& where) {
  std::vector<Person> out;
  const auto it = entry.find(field);
  if (it == entry.end()) return out;
  if (!it->is_array()) throw InputError(where, std::string("'") + field + "' must be a list of names");
  for (const json& p : *it) {
    Person person;
    if (p.is_object()) {
      person.family = text(p, "family");
      person.given = text(p, "given");
      if (person.family.empty()) person.family = text(p, "literal");  // an institution
    }
    if (person.family.empty())
      throw InputError(where, std::string("a name in '") + field + "' has no \"family\" (or \"literal\")");
    out.push_back(std::move(person));
  }
  return out;
}

int issuedYear(const json& entry, const SourceLocation& where) {
  const auto it = entry.find("issued");
  if (it != entry.end() && it->is_object()) {
    const auto parts = it->find("date-parts");
    if (parts != it->end() && parts->is_array() && !parts->empty() && (*parts)[0].is_array() &&
        !(*parts)[0].empty()) {
      const json& year = (*parts)[0][0];
      if (year.is_number_integer()) return year.get<int>();
      if (year.is_string()) return std::atoi(year.get<std::string>().c_str());
    }
  }
  throw InputError(where, "no year: give \"issued\": {\"date-parts\": [[YEAR]]}");
}

std::string familyNames(const std::vector<Person>& names) {
  if (names.size() == 1) return names[0].family;
  if (names.size() == 2) return names[0].family + " and " + names[1].family;
  return names[0].family + " et al.";
}

// "Goral, Cindy M., Kenneth E. Torrance and Donald P. Greenberg": the first name inverted, for sorting by
// eye.
std::string nameList(const std::vector<Person>& names) {
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const Person& p = names[k];
    if (k > 0) out += k + 1 == names.size() ? " and " : ", ";
    if (k == 0)
      out += p.family + (p.given.empty() ? "" : ", " + p.given);
    else
      out += (p.given.empty() ? "" : p.given + " ") + p.family;
  }
  return out;
}

std::string pageRange(const std::string& pages) {
  std::string out;
  for (const char c : pages) out += c == '-' ? std::string("\u2013") : std::string(1, c);
  return out;
}

std::string withStop(const std::string& s) {
  if (s.empty()) return s;
  const char last = s.back();
  return (last == '.' || last == '?' || last == '!') ? s : s + ".";
}

// One entry, author-year: names, year, title, venue, publisher, DOI, each piece ending in a full stop. In
// HTML the text is escaped, the titles of books and venues are in italics and the DOI is a link.
std::string format(const Reference& r, bool html) {
  auto t = [html](const std::string& s) { return html ? escapeHtml(s) : s; };
  auto italic = [&](const std::string& s) { return html ? "<i>" + t(s) + "</i>" : s; };
  std::vector<std::string> parts;
  auto add = [&](const std::string& plain, const std::string& shown) {
    if (!plain.empty()) parts.push_back(shown + (withStop(plain).size() > plain.size() ? "." : ""));
  };
  const bool byEditors = r.authors.empty();
  const std::string names = nameList(byEditors ? r.editors : r.authors) +
                            (byEditors ? (r.editors.size() > 1 ? ", editors" : ", editor") : "");
  add(names, t(names));
  add(std::to_string(r.year), std::to_string(r.year));
  const bool inContainer = r.type == "article-journal" || r.type == "paper-conference" || r.type == "chapter";
  const std::string place = (r.place.empty() || r.publisher.empty() ? "" : r.place + ": ") + r.publisher;
  if (inContainer) {
    add(r.title, t(r.title));
    if (!r.container.empty()) {
      const std::string in = r.type == "article-journal" ? "" : "In ";
      std::string issue =
          r.volume.empty() ? "" : " " + r.volume + (r.issue.empty() ? "" : "(" + r.issue + ")");
      if (!r.pages.empty()) issue += (r.volume.empty() ? ", pp. " : ": ") + pageRange(r.pages);
      add(r.container + issue, in + italic(r.container) + t(issue));
    }
    if (r.type != "article-journal") add(place, t(place));
  } else {
    add(r.title, italic(r.title));
    if (!r.edition.empty()) add(r.edition + " edition", t(r.edition + " edition"));
    const std::string genre =
        r.genre.empty() ? "" : r.genre + (r.publisher.empty() ? "" : ", " + r.publisher);
    add(genre, t(genre));
    const std::string collection =
        r.collection + (r.collection.empty() || r.number.empty() ? "" : " " + r.number);
    add(collection, t(collection));
    if (r.genre.empty()) add(place, t(place));
  }
  add(r.note, t(r.note));
  std::string out;
  for (const std::string& part : parts) out += (out.empty() ? "" : " ") + part;
  // The DOI or address as text: the book's pages link to nothing outside the book.
  const std::string where = r.doi.empty() ? r.url : "doi:" + r.doi;
  if (!where.empty()) out += " " + (html ? "<span class=\"doi\">" + t(where) + "</span>" : where);
  return out;
}

// Gives every entry its label, adding a, b, ... after the year where labels would coincide.
void assignLabels(std::vector<Reference>& entries) {
  std::map<std::string, std::vector<Reference*>> byLabel;
  for (Reference& r : entries) {
    r.label = familyNames(r.authors.empty() ? r.editors : r.authors) + " " + std::to_string(r.year);
    byLabel[r.label].push_back(&r);
  }
  for (auto& [label, same] : byLabel) {
    if (same.size() < 2) continue;
    std::sort(same.begin(), same.end(),
              [](const Reference* a, const Reference* b) { return a->title < b->title; });
    for (std::size_t k = 0; k < same.size(); ++k) same[k]->label += static_cast<char>('a' + k);
  }
}

}  // namespace

const Reference* Bibliography::find(const std::string& key) const {
  for (const Reference& r : entries)
    if (r.key == key) return &r;
  return nullptr;
}

std::string bibliographyPath(const std::string& lessonsDir) {
  return (std::filesystem::path(lessonsDir) / "references.json").string();
}

Bibliography loadBibliography(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parseBibliography(buffer.str(), path);
}

Bibliography parseBibliography(const std::string& source, const std::string& file) {
  json doc;
  try {
    doc = json::parse(source);
  } catch (const json::parse_error& e) {
    const auto at = std::min<std::size_t>(e.byte, source.size());
    const int line =
        1 + static_cast<int>(std::count(source.begin(), source.begin() + static_cast<long>(at), '\n'));
    throw InputError({file, line}, std::string("not valid JSON: ") + e.what());
  }
  if (!doc.is_array()) throw InputError({file, 0, "/"}, "a CSL-JSON bibliography is a list of entries");
  Bibliography bibliography;
  bibliography.file = file;
  std::set<std::string> keys;
  for (std::size_t k = 0; k < doc.size(); ++k) {
    const json& e = doc[k];
    const SourceLocation where{file, 0, "/" + std::to_string(k)};
    if (!e.is_object()) throw InputError(where, "an entry must be an object");
    Reference r;
    r.key = text(e, "id");
    if (r.key.empty()) throw InputError(where, "the entry has no \"id\" (the key lessons cite)");
    if (!keys.insert(r.key).second) throw InputError(where, "the id '" + r.key + "' is used twice");
    r.type = text(e, "type");
    r.title = text(e, "title");
    if (r.title.empty()) throw InputError(where, "entry '" + r.key + "' has no \"title\"");
    r.authors = people(e, "author", where);
    r.editors = people(e, "editor", where);
    if (r.authors.empty() && r.editors.empty())
      throw InputError(where, "entry '" + r.key + "' has no \"author\" (or \"editor\")");
    r.year = issuedYear(e, where);
    for (const auto& [field, member] : kTextFields) r.*member = text(e, field);
    bibliography.entries.push_back(std::move(r));
  }
  assignLabels(bibliography.entries);
  return bibliography;
}

std::string entryHtml(const Reference& r) {
  return format(r, true);
}

std::string entryText(const Reference& r) {
  return format(r, false);
}

std::vector<const Reference*> sortedEntries(const Bibliography& bibliography,
                                            const std::vector<std::string>& keys) {
  std::vector<const Reference*> out;
  for (const std::string& key : keys)
    if (const Reference* r = bibliography.find(key); r && std::find(out.begin(), out.end(), r) == out.end())
      out.push_back(r);
  std::sort(out.begin(), out.end(), [](const Reference* a, const Reference* b) {
    const std::string& fa = (a->authors.empty() ? a->editors : a->authors)[0].family;
    const std::string& fb = (b->authors.empty() ? b->editors : b->authors)[0].family;
    if (fa != fb) return fa < fb;
    if (a->year != b->year) return a->year < b->year;
    return a->label < b->label;
  });
  return out;
}

std::string referenceListHtml(const std::vector<const Reference*>& entries) {
  // One paragraph per entry, so that a long list flows from page to page in the printed book; no blank line
  // between them, so that Markdown passes them through as one HTML block.
  std::string html;
  for (const Reference* r : entries)
    html += "<p class=\"reference\" id=\"ref-" + escapeHtml(r->key) + "\">" + entryHtml(*r) + "</p>\n";
  return html;
}

}  // namespace rt::lesson
