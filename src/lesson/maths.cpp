#include "lesson/maths.h"

#include <md4c.h>

#include <algorithm>
#include <cctype>

#include "core/input_error.h"
#include "lesson/placeholders.h"

namespace rt::lesson {
namespace {

// What one parse of the Markdown reports: the maths spans and the plain text pieces (where references are).
struct Scan {
  const char* base = nullptr;
  std::size_t size = 0;
  std::vector<Formula> formulas;
  std::vector<std::pair<std::size_t, std::size_t>> plain;     // [begin, end) of normal text
  std::vector<std::pair<std::size_t, std::size_t>> unlinked;  // the plain pieces outside a link's text
  int inLink = 0;
  int inMaths = 0;
  bool display = false;
};

bool inBuffer(const Scan& s, const MD_CHAR* text, MD_SIZE size) {
  return text >= s.base && text + size <= s.base + s.size;
}

int enterSpan(MD_SPANTYPE type, void*, void* userdata) {
  auto& s = *static_cast<Scan*>(userdata);
  if (type == MD_SPAN_LATEXMATH || type == MD_SPAN_LATEXMATH_DISPLAY) {
    s.inMaths = 1;
    s.display = type == MD_SPAN_LATEXMATH_DISPLAY;
    s.formulas.push_back({});
    s.formulas.back().display = s.display;
  }
  if (type == MD_SPAN_A) ++s.inLink;
  return 0;
}

int leaveSpan(MD_SPANTYPE type, void*, void* userdata) {
  auto& s = *static_cast<Scan*>(userdata);
  if (type == MD_SPAN_LATEXMATH || type == MD_SPAN_LATEXMATH_DISPLAY) s.inMaths = 0;
  if (type == MD_SPAN_A) --s.inLink;
  return 0;
}

int onText(MD_TEXTTYPE type, const MD_CHAR* text, MD_SIZE size, void* userdata) {
  auto& s = *static_cast<Scan*>(userdata);
  if (!inBuffer(s, text, size)) return 0;  // md4c's own strings (e.g. a line break as " ")
  const std::size_t begin = static_cast<std::size_t>(text - s.base);
  if (s.inMaths && type == MD_TEXT_LATEXMATH) {
    Formula& f = s.formulas.back();
    if (f.end == 0) f.begin = begin;
    f.end = begin + size;
  } else if (type == MD_TEXT_HTML) {
    // An <a ...> written as HTML opens a link as [text](url) does (a block of HTML may hold whole links).
    const std::string html(text, size);
    for (std::size_t at = 0; (at = html.find("<a", at)) != std::string::npos; ++at)
      if (at + 2 < html.size() && (html[at + 2] == ' ' || html[at + 2] == '>')) ++s.inLink;
    for (std::size_t at = 0; (at = html.find("</a>", at)) != std::string::npos; ++at)
      if (s.inLink > 0) --s.inLink;
  } else if (type == MD_TEXT_NORMAL) {
    s.plain.emplace_back(begin, begin + size);
    if (s.inLink == 0) s.unlinked.emplace_back(begin, begin + size);
  }
  return 0;
}

int noBlock(MD_BLOCKTYPE, void*, void*) {
  return 0;
}

Scan scan(const std::string& markdown) {
  Scan s;
  s.base = markdown.data();
  s.size = markdown.size();
  MD_PARSER parser{};
  parser.flags = MD_FLAG_TABLES | MD_FLAG_STRIKETHROUGH | MD_FLAG_LATEXMATHSPANS;
  parser.enter_block = noBlock;
  parser.leave_block = noBlock;
  parser.enter_span = enterSpan;
  parser.leave_span = leaveSpan;
  parser.text = onText;
  md_parse(markdown.data(), static_cast<MD_SIZE>(markdown.size()), &parser, &s);
  // An empty formula ($$ $$) has no text piece: nothing to typeset.
  s.formulas.erase(
      std::remove_if(s.formulas.begin(), s.formulas.end(), [](const Formula& f) { return f.end == 0; }),
      s.formulas.end());
  return s;
}

int lineAt(const std::string& text, std::size_t pos, int firstLine) {
  return firstLine + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

bool labelChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
}

// The {#eq:label} after a displayed equation's closing $$: its label and the range to remove.
struct LabelMark {
  std::string label;
  std::size_t begin = 0, end = 0;
};

LabelMark labelAfter(const std::string& text, std::size_t texEnd) {
  std::size_t at = text.find("$$", texEnd);
  if (at == std::string::npos) return {};
  at += 2;
  std::size_t p = at;
  while (p < text.size() && (text[p] == ' ' || text[p] == '\t')) ++p;
  if (text.compare(p, 5, "{#eq:") != 0) return {};
  std::size_t q = p + 5;
  while (q < text.size() && labelChar(text[q])) ++q;
  if (q >= text.size() || text[q] != '}' || q == p + 5) return {};
  return {text.substr(p + 5, q - p - 5), at, q + 1};
}

}  // namespace

std::vector<Formula> findFormulas(const std::string& markdown, int firstLine) {
  Scan s = scan(markdown);
  for (Formula& f : s.formulas) {
    f.tex = markdown.substr(f.begin, f.end - f.begin);
    f.line = lineAt(markdown, f.begin, firstLine);
    if (f.display) f.label = labelAfter(markdown, f.end).label;
  }
  return s.formulas;
}

EquationNumbers numberEquations(const Lesson& lesson) {
  EquationNumbers numbers;
  int count = 0;
  auto add = [&](const std::string& text, int firstLine) {
    for (const Formula& f : findFormulas(text, firstLine)) {
      if (!f.display) continue;
      const std::string number = std::to_string(lesson.order) + "." + std::to_string(++count);
      numbers.byLine[f.line] = number;
      if (f.label.empty()) continue;
      if (!numbers.byLabel.emplace(f.label, number).second)
        throw InputError({lesson.file, f.line}, "equation label 'eq:" + f.label + "' is used twice");
    }
  };
  add(lesson.intro, lesson.introLine);
  for (const Step& step : lesson.steps) add(step.text, step.textLine);
  return numbers;
}

std::string prepareMaths(const std::string& markdown, int firstLine, const std::string& file,
                         const EquationNumbers& numbers) {
  const Scan s = scan(markdown);
  // Edits from the end backwards, so that earlier offsets stay valid.
  struct Edit {
    std::size_t begin, end;
    std::string text;
  };
  std::vector<Edit> edits;
  for (const Formula& f : s.formulas) {
    if (!f.display) continue;
    const auto number = numbers.byLine.find(lineAt(markdown, f.begin, firstLine));
    if (number == numbers.byLine.end()) continue;
    const LabelMark mark = labelAfter(markdown, f.end);
    if (!mark.label.empty()) edits.push_back({mark.begin, mark.end, ""});
    edits.push_back({f.end, f.end, " \\tag{" + number->second + "}"});
    // The anchor a reference links to: just before the opening $$.
    const std::size_t open = markdown.rfind("$$", f.begin);
    if (!mark.label.empty() && open != std::string::npos)
      edits.push_back({open, open, "<span class=\"eq-anchor\" id=\"eq-" + mark.label + "\"></span>"});
  }
  for (const auto& [begin, end] : s.plain) {
    // A $$ left in the text is maths the parser did not take as maths: unclosed, or cut by a line that is
    // Markdown of its own (a line of '=' or '-' under text is a heading, a blank line ends the paragraph).
    const std::size_t dollars = markdown.find("$$", begin);
    if (dollars != std::string::npos && dollars + 2 <= end)
      throw InputError({file, lineAt(markdown, dollars, firstLine)},
                       "'$$' does not start or end a displayed formula here: close it, and keep its lines "
                       "free of blank lines and of lines that Markdown reads as headings, lists or quotes");
  }
  for (const LabelReference& r : findReferences(markdown, firstLine, "eq")) {
    const auto number = numbers.byLabel.find(r.label);
    if (number == numbers.byLabel.end())
      throw InputError({file, r.line}, "reference to an unknown equation '@eq:" + r.label +
                                           "' (label a displayed equation with {#eq:" + r.label +
                                           "} after its closing $$)");
    edits.push_back({r.begin, r.end, "[(" + number->second + ")](#eq-" + r.label + ")"});
  }
  std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.begin > b.begin; });
  std::string out = markdown;
  for (const Edit& e : edits) out.replace(e.begin, e.end - e.begin, e.text);
  return out;
}

std::vector<LabelReference> findReferences(const std::string& markdown, int firstLine,
                                           const std::string& kind) {
  std::vector<LabelReference> found;
  const std::string mark = "@" + kind + ":";
  for (const auto& [begin, end] : scan(markdown).plain) {
    std::size_t at = begin;
    while ((at = markdown.find(mark, at)) != std::string::npos && at < end) {
      std::size_t q = at + mark.size();
      while (q < end && labelChar(markdown[q])) ++q;
      while (q > at + mark.size() && !std::isalnum(static_cast<unsigned char>(markdown[q - 1]))) --q;
      found.push_back(
          {at, q, markdown.substr(at + mark.size(), q - at - mark.size()), lineAt(markdown, at, firstLine)});
      at = q;
    }
  }
  return found;
}

std::vector<std::pair<std::size_t, std::size_t>> plainTextPieces(const std::string& markdown) {
  return scan(markdown).plain;
}

std::vector<std::pair<std::size_t, std::size_t>> unlinkedTextPieces(const std::string& markdown) {
  return scan(markdown).unlinked;
}

std::vector<Formula> lessonFormulas(const Lesson& lesson) {
  std::vector<Formula> all;
  auto add = [&](const std::string& text, int firstLine) {
    for (Formula f : findFormulas(text, firstLine)) {
      // Sample numbers where the placeholders are: a percentage keeps its '%' (a TeX comment unless escaped).
      std::string tex = f.tex;
      const auto placeholders = findPlaceholders(tex, f.line);
      for (auto p = placeholders.rbegin(); p != placeholders.rend(); ++p)
        tex.replace(p->begin, p->end - p->begin, p->format == "%" ? "12.5%" : "0.125");
      f.tex = tex;
      all.push_back(std::move(f));
    }
  };
  add(lesson.intro, lesson.introLine);
  for (const Step& step : lesson.steps) add(step.text, step.textLine);
  return all;
}

std::string equationStyleSheet() {
  // KaTeX places \tag's number absolutely at the right of the display, over whatever reaches there. As a
  // flex row of the equation's pieces (KaTeX cuts it into .base boxes at its relations) and the number, with
  // the free space before the first piece and before the number (or after the last piece), the equation is
  // centred in the room the number leaves; a pane too narrow for it breaks the equation at a relation and
  // puts the number under it, as LaTeX does, instead of over its last terms.
  return R"(.katex-display > .katex > .katex-html { display: flex; flex-wrap: wrap; align-items: baseline; }
.katex-display > .katex > .katex-html > .base:first-child { margin-left: auto; }
.katex-display > .katex > .katex-html > .base:last-child { margin-right: auto; }
.katex-display > .katex > .katex-html > .tag { position: static !important; padding-left: 1em; flex: none;
                                               margin-left: auto; }
)";
}

}  // namespace rt::lesson
