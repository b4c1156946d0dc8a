#include "lesson/citations.h"

#include <algorithm>
#include <cctype>

#include "core/input_error.h"
#include "lesson/maths.h"

namespace rt::lesson {
namespace {

bool keyChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// "@key" or "@key, p. 12".
CitedWork parseWork(const std::string& item, const SourceLocation& where) {
  const std::string t = trim(item);
  std::size_t q = 1;
  while (q < t.size() && keyChar(t[q])) ++q;
  if (t.empty() || t[0] != '@' || q == 1)
    throw InputError(where, "a citation lists keys as '@key', separated by ';': '" + item + "'");
  CitedWork work{t.substr(1, q - 1), {}};
  const std::string rest = trim(t.substr(q));
  if (!rest.empty()) {
    if (rest[0] != ',')
      throw InputError(where,
                       "after the key '@" + work.key + "' a citation takes ', locator' (e.g. ', p. 12')");
    work.locator = trim(rest.substr(1));
  }
  return work;
}

// Markdown link titles are in double quotes: escape what would end them.
std::string linkTitle(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::vector<Citation> findCitations(const std::string& markdown, int firstLine, const std::string& file) {
  // Only normal text counts: a '[@' in code or maths is not a citation.
  std::vector<bool> plain(markdown.size(), false);
  for (const auto& [begin, end] : plainTextPieces(markdown))
    std::fill(plain.begin() + begin, plain.begin() + end, true);
  std::vector<Citation> found;
  for (std::size_t at = markdown.find("[@"); at != std::string::npos; at = markdown.find("[@", at + 1)) {
    if (!plain[at] || !plain[at + 1]) continue;
    // The label references (@eq:, @alg:, @lesson:) are not citations, even in brackets.
    bool reference = false;
    for (const char* kind : {"@eq:", "@alg:", "@lesson:", "@Lesson:"})
      reference = reference || markdown.compare(at + 1, std::char_traits<char>::length(kind), kind) == 0;
    if (reference) continue;
    const int line = firstLine + static_cast<int>(std::count(markdown.begin(),
                                                             markdown.begin() + static_cast<long>(at), '\n'));
    const SourceLocation where{file, line};
    const std::size_t lineEnd = markdown.find('\n', at);
    const std::size_t close = markdown.find(']', at);
    if (close == std::string::npos || (lineEnd != std::string::npos && close > lineEnd))
      throw InputError(where, "a citation '[@' is not closed by ']' on its line");
    Citation c;
    c.line = line;
    c.begin = at;
    c.end = close + 1;
    const std::string inside = markdown.substr(at + 1, close - at - 1);
    for (std::size_t from = 0;;) {
      const std::size_t semicolon = inside.find(';', from);
      c.works.push_back(parseWork(inside.substr(from, semicolon - from), where));
      if (semicolon == std::string::npos) break;
      from = semicolon + 1;
    }
    found.push_back(std::move(c));
    at = close;
  }
  return found;
}

std::vector<std::string> citedKeys(const std::string& markdown, int firstLine, const std::string& file) {
  std::vector<std::string> keys;
  for (const Citation& c : findCitations(markdown, firstLine, file))
    for (const CitedWork& w : c.works)
      if (std::find(keys.begin(), keys.end(), w.key) == keys.end()) keys.push_back(w.key);
  return keys;
}

std::vector<std::string> citedKeys(const Lesson& lesson) {
  std::vector<std::string> keys = citedKeys(lesson.intro, lesson.introLine, lesson.file);
  for (const Step& step : lesson.steps)
    for (const std::string& key : citedKeys(step.text, step.textLine, lesson.file))
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  return keys;
}

std::string prepareCitations(const std::string& markdown, int firstLine, const std::string& file,
                             const Bibliography& bibliography) {
  const std::vector<Citation> citations = findCitations(markdown, firstLine, file);
  std::string out = markdown;
  for (auto c = citations.rbegin(); c != citations.rend(); ++c) {
    std::string links;
    for (const CitedWork& w : c->works) {
      const Reference* r = bibliography.find(w.key);
      if (!r)
        throw InputError({file, c->line},
                         "citation of an unknown work '@" + w.key + "' (" +
                             (bibliography.file.empty() ? std::string("there is no lessons/references.json")
                                                        : "add it to " + bibliography.file) +
                             ")");
      links += (links.empty() ? "" : "; ") + std::string("[") + r->label +
               (w.locator.empty() ? "" : ", " + w.locator) + "](#ref-" + r->key + " \"" +
               linkTitle(entryText(*r)) + "\")";
    }
    out.replace(c->begin, c->end - c->begin, "(" + links + ")");
  }
  return out;
}

}  // namespace rt::lesson
