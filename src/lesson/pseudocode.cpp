#include "lesson/pseudocode.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "core/input_error.h"
#include "lesson/markdown_html.h"

namespace rt::lesson {
namespace {

const std::set<std::string>& keywords() {
  static const std::set<std::string> words{"procedure", "function", "for",      "each",     "do",     "while",
                                           "repeat",    "until",    "if",       "then",     "else",   "end",
                                           "return",    "break",    "continue", "parallel", "forever"};
  return words;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

bool idChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
}

// A line's pieces: text outside maths and the TeX between single dollars ("\$" is a dollar sign).
struct Piece {
  std::string text;
  bool maths = false;
};

std::vector<Piece> pieces(const std::string& code, const SourceLocation& where) {
  std::vector<Piece> out(1);
  for (std::size_t k = 0; k < code.size(); ++k) {
    if (code[k] == '\\' && k + 1 < code.size() && code[k + 1] == '$' && !out.back().maths) {
      out.back().text += '$';
      ++k;
    } else if (code[k] == '$') {
      out.push_back({"", !out.back().maths});
    } else {
      out.back().text += code[k];
    }
  }
  if (out.back().maths) throw InputError(where, "a '$' in the listing's line opens maths that is not closed");
  return out;
}

// Text with its keywords in bold, HTML-escaped.
std::string boldKeywords(const std::string& text) {
  std::string out;
  for (std::size_t k = 0; k < text.size();) {
    if (!std::isalpha(static_cast<unsigned char>(text[k]))) {
      out += escapeHtml(std::string(1, text[k++]));
      continue;
    }
    std::size_t q = k;
    while (q < text.size() && (std::isalnum(static_cast<unsigned char>(text[q])) || text[q] == '_')) ++q;
    const std::string word = text.substr(k, q - k);
    out += keywords().count(word) ? "<b>" + word + "</b>" : escapeHtml(word);
    k = q;
  }
  return out;
}

std::string lineHtml(const std::string& code, const SourceLocation& where, bool withKeywords) {
  std::string html;
  for (const Piece& p : pieces(code, where)) {
    if (p.maths)
      html += "<x-equation>" + escapeHtml(p.text) + "</x-equation>";
    else
      html += withKeywords ? boldKeywords(p.text) : escapeHtml(p.text);
  }
  return html;
}

int lineOf(const std::string& text, std::size_t pos, int firstLine) {
  return firstLine + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

Pseudocode parseBody(const std::vector<std::string>& body, int firstBodyLine, const SourceLocation& fence) {
  Pseudocode p;
  p.line = fence.line;
  std::size_t k = 0;
  for (; k < body.size(); ++k) {
    const std::string t = trim(body[k]);
    if (t.rfind("id:", 0) == 0) {
      p.id = trim(t.substr(3));
    } else if (t.rfind("caption:", 0) == 0) {
      p.caption = trim(t.substr(8));
    } else {
      break;
    }
  }
  if (p.id.empty() || !std::all_of(p.id.begin(), p.id.end(), idChar))
    throw InputError(fence, "a ```pseudocode block starts with 'id: name' (letters, digits, '-', '_')");
  if (p.caption.empty())
    throw InputError(fence, "the ```pseudocode block '" + p.id + "' has no 'caption:' line");
  for (; k < body.size(); ++k) {
    std::string code = body[k];
    if (trim(code).empty()) continue;
    PseudocodeLine line;
    line.line = firstBodyLine + static_cast<int>(k);
    const std::size_t note = code.find(" // ");
    if (note != std::string::npos) {
      line.source = trim(code.substr(note + 4));
      code = code.substr(0, note);
    }
    const std::size_t indent = code.find_first_not_of(' ');
    line.indent = static_cast<int>(indent) / 2;
    line.code = trim(code);
    pieces(line.code, {fence.file, line.line});  // an unclosed '$' is reported here, at its line
    p.lines.push_back(std::move(line));
  }
  if (p.lines.empty()) throw InputError(fence, "the ```pseudocode block '" + p.id + "' has no lines");
  return p;
}

// A file or function name in the narrow column of notes may break only where a reader would split it: after
// an underscore and between the words of a camel-case name, never inside a word.
std::string breakableName(const std::string& name) {
  std::string html;
  for (std::size_t k = 0; k < name.size(); ++k) {
    const char c = name[k];
    const bool wordStarts = k > 0 && std::isupper(static_cast<unsigned char>(c)) &&
                            std::islower(static_cast<unsigned char>(name[k - 1]));
    if (wordStarts) html += "<wbr>";
    html += escapeHtml(std::string(1, c));
    if (c == '_' || c == '/') html += "<wbr>";
  }
  return html;
}

}  // namespace

std::vector<Pseudocode> findPseudocode(const std::string& markdown, int firstLine, const std::string& file) {
  std::vector<Pseudocode> found;
  std::size_t blockBegin = 0;
  bool inFence = false, listing = false;
  std::vector<std::string> body;
  for (std::size_t at = 0; at < markdown.size();) {
    std::size_t next = markdown.find('\n', at);
    next = next == std::string::npos ? markdown.size() : next + 1;
    const std::string line = markdown.substr(at, next - at - (markdown[next - 1] == '\n' ? 1 : 0));
    const std::string t = trim(line);
    const bool fence = t.rfind("```", 0) == 0;
    if (!inFence && fence) {
      inFence = true;
      listing = trim(t.substr(3)) == "pseudocode";
      blockBegin = at;
      body.clear();
    } else if (inFence && fence) {
      inFence = false;
      if (listing) {
        const int fenceLine = lineOf(markdown, blockBegin, firstLine);
        Pseudocode p = parseBody(body, fenceLine + 1, {file, fenceLine});
        p.begin = blockBegin;
        p.end = next;
        found.push_back(std::move(p));
      }
    } else if (inFence && listing) {
      body.push_back(line);
    }
    at = next;
  }
  if (inFence && listing)
    throw InputError({file, lineOf(markdown, blockBegin, firstLine)},
                     "the ```pseudocode block is not closed");
  return found;
}

AlgorithmNumbers numberAlgorithms(const Lesson& lesson) {
  AlgorithmNumbers numbers;
  int count = 0;
  auto add = [&](const std::string& text, int firstLine) {
    for (const Pseudocode& p : findPseudocode(text, firstLine, lesson.file))
      if (!numbers.emplace(p.id, std::to_string(lesson.order) + "." + std::to_string(++count)).second)
        throw InputError({lesson.file, p.line}, "the algorithm id '" + p.id + "' is used twice");
  };
  add(lesson.intro, lesson.introLine);
  for (const Step& step : lesson.steps) add(step.text, step.textLine);
  return numbers;
}

std::string pseudocodeHtml(const Pseudocode& listing, const std::string& number) {
  // No blank line anywhere: Markdown keeps an HTML block together up to the first one.
  std::string html = "<figure class=\"algorithm\" id=\"alg-" + listing.id + "\"><figcaption><b>Algorithm " +
                     number + "</b> " + lineHtml(listing.caption, {"", listing.line}, false) +
                     "</figcaption>\n<table class=\"algorithm-lines\">\n";
  int n = 0;
  for (const PseudocodeLine& l : listing.lines) {
    // Wrapped lines hang under their first word; each level of indentation is 1.5em.
    // The whole line names its code on hover too: a narrow page hides the column of notes.
    const std::string title = l.source.empty() ? "" : " title=\"src/" + escapeHtml(l.source) + "\"";
    html += "<tr" + title + "><td class=\"alg-number\">" + std::to_string(++n) +
            "</td><td class=\"alg-code\" style=\"padding-left: calc(" + std::to_string(l.indent) +
            " * 1.5em + 1em)\">" + lineHtml(l.code, {"", l.line}, true) + "</td><td class=\"alg-source\">";
    if (!l.source.empty()) {
      // The file's name and the function, small; the path under src/ on hover.
      const std::size_t colon = l.source.find(": ");
      const std::string path = l.source.substr(0, colon);
      const std::string name = path.substr(path.rfind('/') + 1);
      html += "<span title=\"src/" + escapeHtml(l.source) + "\">" + breakableName(name);
      if (colon != std::string::npos) html += "<br>" + breakableName(l.source.substr(colon + 2));
      html += "</span>";
    }
    html += "</td></tr>\n";
  }
  return html + "</table></figure>\n\n";
}

std::string preparePseudocode(const std::string& markdown, int firstLine, const std::string& file,
                              const AlgorithmNumbers& numbers) {
  struct Edit {
    std::size_t begin, end;
    std::string text;
  };
  std::vector<Edit> edits;
  for (const LabelReference& r : findReferences(markdown, firstLine, "alg")) {
    const auto number = numbers.find(r.label);
    if (number == numbers.end())
      throw InputError({file, r.line}, "reference to an unknown algorithm '@alg:" + r.label +
                                           "' (name a ```pseudocode block with 'id: " + r.label + "')");
    edits.push_back({r.begin, r.end, "[Algorithm " + number->second + "](#alg-" + r.label + ")"});
  }
  for (const Pseudocode& p : findPseudocode(markdown, firstLine, file)) {
    const auto number = numbers.find(p.id);
    edits.push_back({p.begin, p.end, pseudocodeHtml(p, number == numbers.end() ? "" : number->second)});
  }
  std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.begin > b.begin; });
  std::string out = markdown;
  for (const Edit& e : edits) out.replace(e.begin, e.end - e.begin, e.text);
  return out;
}

std::vector<Formula> algorithmFormulas(const Lesson& lesson) {
  std::vector<Formula> all;
  auto add = [&](const std::string& text, int firstLine) {
    for (const Pseudocode& p : findPseudocode(text, firstLine, lesson.file)) {
      auto addLine = [&](const std::string& code, int line) {
        for (const Piece& piece : pieces(code, {lesson.file, line}))
          if (piece.maths) all.push_back({piece.text, false, line, "", 0, 0});
      };
      addLine(p.caption, p.line);
      for (const PseudocodeLine& l : p.lines) addLine(l.code, l.line);
    }
  };
  add(lesson.intro, lesson.introLine);
  for (const Step& step : lesson.steps) add(step.text, step.textLine);
  return all;
}

}  // namespace rt::lesson
