#include "lesson/glossary.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "homework/plain_text.h"
#include "lesson/markdown_html.h"
#include "lesson/maths.h"

namespace rt::lesson {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool letter(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
}

// The whole-word uses of the term in the given pieces of the text ("form factor", "form factors").
std::vector<std::pair<std::size_t, std::size_t>> usesIn(
    const std::string& text, const std::vector<std::pair<std::size_t, std::size_t>>& pieces,
    const std::string& term) {
  const std::string t = lower(term);
  std::vector<std::pair<std::size_t, std::size_t>> found;
  for (const auto& [begin, end] : pieces) {
    const std::string piece = lower(text.substr(begin, end - begin));
    for (std::size_t at = piece.find(t); at != std::string::npos; at = piece.find(t, at + 1)) {
      std::size_t after = at + t.size();
      if (after < piece.size() && piece[after] == 's') ++after;
      if ((at == 0 || !letter(piece[at - 1])) && (after >= piece.size() || !letter(piece[after])))
        found.emplace_back(begin + at, begin + after);
    }
  }
  return found;
}

bool uses(const std::string& text, const std::string& term) {
  return !usesIn(text, plainTextPieces(text), term).empty();
}

// Definitions are plain text with maths: the maths becomes <x-equation> for the typesetter.
std::string definitionHtml(const std::string& text) {
  std::string html;
  bool maths = false;
  std::string piece;
  auto flush = [&] {
    html += maths ? "<x-equation>" + escapeHtml(piece) + "</x-equation>" : escapeHtml(piece);
    piece.clear();
  };
  for (const char c : text) {
    if (c == '$') {
      flush();
      maths = !maths;
    } else {
      piece += c;
    }
  }
  flush();
  return html;
}

// A term's paragraph as the Glossary chapter and a page's definitions open it, before any link.
std::string definitionParagraph(const GlossaryEntry& e) {
  return "<p class=\"glossary\" id=\"" + glossaryAnchor(e.term) + "\"><b>" + escapeHtml(e.term) +
         "</b>: " + definitionHtml(e.definition);
}

}  // namespace

std::string definitionText(const GlossaryEntry& entry) {
  return homework::plainText(entry.definition);
}

std::vector<TermUse> firstTermUses(const std::string& markdown, const std::vector<GlossaryEntry>& entries) {
  std::vector<const GlossaryEntry*> byLength;
  for (const GlossaryEntry& t : entries) byLength.push_back(&t);
  std::stable_sort(byLength.begin(), byLength.end(), [](const GlossaryEntry* a, const GlossaryEntry* b) {
    return a->term.size() > b->term.size();
  });
  std::vector<TermUse> found;
  for (const GlossaryEntry* t : byLength)
    for (const auto& use : termUses(markdown, t->term)) {
      const bool free = std::none_of(found.begin(), found.end(), [&](const TermUse& u) {
        return use.first < u.range.second && u.range.first < use.second;
      });
      if (!free) continue;
      found.push_back({t, use});
      break;
    }
  return found;
}

std::string linkTermsToDefinitions(const std::string& markdown, const std::vector<GlossaryEntry>& entries,
                                   std::vector<const GlossaryEntry*>& linked) {
  std::vector<TermUse> uses;
  for (const TermUse& u : firstTermUses(markdown, entries))
    if (!u.entry->indexOnly && std::find(linked.begin(), linked.end(), u.entry) == linked.end())
      uses.push_back(u);
  // From the end, so that the offsets still ahead stay valid.
  std::sort(uses.begin(), uses.end(), [](const TermUse& a, const TermUse& b) { return a.range > b.range; });
  std::string text = markdown;
  for (const TermUse& u : uses) {
    const auto [begin, end] = u.range;
    text.replace(begin, end - begin,
                 "<a class=\"term\" href=\"#" + glossaryAnchor(u.entry->term) + "\" title=\"" +
                     escapeHtml(definitionText(*u.entry)) + "\">" + text.substr(begin, end - begin) + "</a>");
  }
  for (auto it = uses.rbegin(); it != uses.rend(); ++it) linked.push_back(it->entry);
  return text;
}

std::string termDefinitionsHtml(const std::vector<const GlossaryEntry*>& terms, int level) {
  if (terms.empty()) return "";
  // One paragraph per term and no blank line: Markdown passes the block through whole.
  const std::string h = "h" + std::to_string(level);
  std::string html = "<" + h + " class=\"terms\">Terms</" + h + ">\n\n";
  for (const GlossaryEntry* e : terms) html += definitionParagraph(*e) + "</p>\n";
  return html;
}

std::vector<std::pair<std::size_t, std::size_t>> termUses(const std::string& markdown,
                                                          const std::string& term) {
  return usesIn(markdown, unlinkedTextPieces(markdown), term);
}

std::string glossaryAnchor(const std::string& term) {
  std::string id = "gl-";
  for (const char c : lower(term)) id += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return id;
}

std::string glossaryPath(const std::string& lessonsDir) {
  return lessonsDir + "/glossary.json";
}

std::vector<GlossaryEntry> loadGlossary(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::stringstream buffer;
  buffer << in.rdbuf();
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(buffer.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError({path}, std::string("not valid JSON: ") + e.what());
  }
  if (!doc.is_array())
    throw InputError({path, 0, "/"}, "the glossary is a list of {\"term\", \"definition\"}");
  std::vector<GlossaryEntry> entries;
  std::set<std::string> terms;
  for (std::size_t k = 0; k < doc.size(); ++k) {
    const SourceLocation where{path, 0, "/" + std::to_string(k)};
    const auto& e = doc[k];
    if (!e.is_object() || !e.value("term", nlohmann::json()).is_string())
      throw InputError(where, "an entry needs a \"term\", as text");
    const auto indexOnly = e.value("index-only", nlohmann::json(false));
    if (!indexOnly.is_boolean()) throw InputError(where, "\"index-only\" is true or false");
    GlossaryEntry entry{e["term"].get<std::string>(), "", indexOnly.get<bool>()};
    if (entry.indexOnly) {
      if (e.contains("definition"))
        throw InputError(where,
                         "the index-only term '" + entry.term + "' has a definition: drop one of them");
    } else {
      if (!e.value("definition", nlohmann::json()).is_string())
        throw InputError(where,
                         "the term '" + entry.term + "' needs a \"definition\" (or \"index-only\": true)");
      entry.definition = e["definition"].get<std::string>();
    }
    if (entry.term.empty() || (entry.definition.empty() && !entry.indexOnly))
      throw InputError(where, "an empty term or definition");
    if (std::count(entry.definition.begin(), entry.definition.end(), '$') % 2 != 0)
      throw InputError(where,
                       "the definition of '" + entry.term + "' opens maths with '$' and does not close it");
    if (!terms.insert(lower(entry.term)).second)
      throw InputError(where, "the term '" + entry.term + "' is defined twice");
    entries.push_back(std::move(entry));
  }
  return entries;
}

std::optional<FirstUse> firstUse(const std::string& term, const std::vector<Lesson>& lessons) {
  for (const Lesson& l : lessons) {
    if (uses(l.title, term) || uses(l.intro, term)) return FirstUse{&l, 0};
    for (std::size_t k = 0; k < l.steps.size(); ++k)
      if (uses(l.steps[k].title, term) || uses(l.steps[k].text, term))
        return FirstUse{&l, static_cast<int>(k + 1)};
  }
  return std::nullopt;
}

std::string glossaryHtml(const std::vector<GlossaryEntry>& entries, const std::vector<Lesson>& lessons) {
  std::vector<const GlossaryEntry*> sorted;
  for (const GlossaryEntry& e : entries)
    if (!e.indexOnly) sorted.push_back(&e);
  std::sort(sorted.begin(), sorted.end(),
            [](const GlossaryEntry* a, const GlossaryEntry* b) { return lower(a->term) < lower(b->term); });
  // One paragraph per term and no blank line: Markdown passes the block through whole.
  std::string html;
  for (const GlossaryEntry* e : sorted) {
    html += definitionParagraph(*e);
    if (const auto use = firstUse(e->term, lessons)) {
      const Lesson& l = *use->lesson;
      const std::string order = std::to_string(l.order);
      const std::string target = use->section == 0 ? "top" : "s" + order + "-" + std::to_string(use->section);
      const std::string where = use->section == 0 ? "chapter " + order + ", " + escapeHtml(l.title)
                                                  : "section " + order + "." + std::to_string(use->section) +
                                                        ", " + escapeHtml(l.steps[use->section - 1].title);
      html += " First used in <a href=\"" + l.id + ".html#" + target + "\">" + where + "</a>.";
    }
    html += "</p>\n";
  }
  return html;
}

}  // namespace rt::lesson
