#include "lesson/lesson_parser.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "core/formfactor/formfactor_method.h"
#include "core/input_error.h"
#include "core/solvers/solver.h"
#include "lesson/placeholders.h"
#include "lesson/step_block.h"
#include "lesson/step_keys.h"
#include "lesson/value_parsing.h"

namespace rt::lesson {
namespace {

std::string trim(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  const auto end = s.find_last_not_of(" \t\r");
  return s.substr(begin, end - begin + 1);
}

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

bool contains(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

// Strips leading and trailing blank lines from a block of Markdown, keeping its inner layout.
std::string trimBlankLines(const std::vector<std::string>& lines, int* firstLine) {
  std::size_t begin = 0, end = lines.size();
  while (begin < end && trim(lines[begin]).empty()) ++begin;
  while (end > begin && trim(lines[end - 1]).empty()) --end;
  if (firstLine) *firstLine += static_cast<int>(begin);
  std::string out;
  for (std::size_t i = begin; i < end; ++i) out += lines[i] + "\n";
  return out;
}

class Parser {
 public:
  Parser(const std::string& text, std::string id, std::string file)
      : lines_(splitLines(text)), file_(std::move(file)) {
    lesson_.id = std::move(id);
    lesson_.file = file_;
  }

  Lesson parse() {
    std::size_t at = parseHeader();
    parseBody(at);
    if (lesson_.steps.empty())
      fail(static_cast<int>(lines_.size()), "the lesson has no steps (a step starts with '## Title')");
    checkFigureNames();
    return lesson_;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& message) const {
    throw InputError({file_, line}, message);
  }

  std::size_t parseHeader() {
    if (lines_.empty() || trim(lines_[0]) != "---")
      fail(1, "a lesson starts with a header between '---' lines (title, order, chapter, summary)");
    std::set<std::string> seen;
    for (std::size_t i = 1; i < lines_.size(); ++i) {
      const int line = static_cast<int>(i) + 1;
      const std::string t = trim(lines_[i]);
      if (t == "---") {
        if (!seen.count("title")) fail(line, "the header has no 'title'");
        if (!seen.count("order")) fail(line, "the header has no 'order' (the lesson's position in the book)");
        return i + 1;
      }
      if (t.empty() || t[0] == '#') continue;
      const auto colon = t.find(':');
      if (colon == std::string::npos) fail(line, "expected 'key: value' in the header, got '" + t + "'");
      const std::string key = trim(t.substr(0, colon));
      const std::string value = trim(t.substr(colon + 1));
      if (!seen.insert(key).second) fail(line, "'" + key + "' is given twice");
      if (key == "title") {
        if (value.empty()) fail(line, "the title is empty");
        lesson_.title = value;
      } else if (key == "order") {
        lesson_.order = parseInt(value, {file_, line}, "order", 0, 100000);
      } else if (key == "chapter") {
        lesson_.chapter = value;
      } else if (key == "summary") {
        lesson_.summary = value;
      } else {
        fail(line, "unknown header key '" + key + "' (known: title, order, chapter, summary)");
      }
    }
    fail(static_cast<int>(lines_.size()), "the header is not closed by a '---' line");
  }

  void parseBody(std::size_t at) {
    std::vector<std::string> text;
    int textLine = static_cast<int>(at) + 1;
    bool inFence = false;
    Step* step = nullptr;
    auto flush = [&] {
      int first = textLine;
      std::string body = trimBlankLines(text, &first);
      if (step) {
        step->text = body;
        step->textLine = first;
      } else {
        lesson_.intro = body;
        lesson_.introLine = first;
      }
      checkPlaceholders(body, first);
      text.clear();
    };
    for (std::size_t i = at; i < lines_.size(); ++i) {
      const int line = static_cast<int>(i) + 1;
      const std::string& raw = lines_[i];
      const std::string t = trim(raw);
      if (!inFence && startsWith(raw, "## ")) {
        if (step) finishStepBlock(*step);
        flush();
        lesson_.steps.emplace_back();
        step = &lesson_.steps.back();
        step->index = static_cast<int>(lesson_.steps.size()) - 1;
        step->line = line;
        step->title = trim(raw.substr(3));
        if (step->title.empty()) fail(line, "the step has no title");
        textLine = line + 1;
        continue;
      }
      if (!inFence && t == "```step") {
        if (!step) fail(line, "a ```step block must follow a step heading ('## Title')");
        if (!step->fields.empty() || stepBlockSeen_) fail(line, "the step already has a ```step block");
        i = parseStepBlock(i + 1, *step);
        stepBlockSeen_ = true;
        // Keep line numbers of the text right: the block is replaced by nothing, text resumes after it.
        if (text.empty() ||
            std::all_of(text.begin(), text.end(), [](const auto& l) { return trim(l).empty(); })) {
          text.clear();
          textLine = static_cast<int>(i) + 2;
        } else {
          fail(line, "put the ```step block right after the step heading, before the text");
        }
        continue;
      }
      if (!inFence && t == "```question") {
        if (!step) fail(line, "a ```question block belongs to an exercise step");
        if (step->questionLine) fail(line, "the step already has a ```question block");
        step->questionLine = line;
        const std::size_t end = parseQuestionBlock(i + 1, *step);
        // Blank lines in its place keep the text's line numbers right.
        text.insert(text.end(), end - i + 1, "");
        i = end;
        continue;
      }
      if (startsWith(t, "```")) inFence = !inFence;
      text.push_back(raw);
    }
    if (inFence) fail(static_cast<int>(lines_.size()), "a ``` code block is not closed");
    if (step) finishStepBlock(*step);
    flush();
  }

  // Reads `key: value` lines up to the closing fence; returns the index of the closing fence.
  std::size_t parseStepBlock(std::size_t at, Step& step) {
    for (std::size_t i = at; i < lines_.size(); ++i) {
      const int line = static_cast<int>(i) + 1;
      const std::string t = trim(lines_[i]);
      if (t == "```") return i;
      if (t.empty() || t[0] == '#') continue;
      const auto colon = t.find(':');
      if (colon == std::string::npos) fail(line, "expected 'key: value' in the step block, got '" + t + "'");
      const std::string key = trim(t.substr(0, colon));
      const std::string value = trim(t.substr(colon + 1));
      const bool isReflectance = startsWith(key, "reflectance.") && key.size() > 12;
      if (!isReflectance && !contains(stepKeys(), key))
        fail(line, "unknown step key '" + key + "' (known: " + joinedNames(stepKeys()) +
                       ", reflectance.<surface>)");
      if (value.empty()) fail(line, "'" + key + "' has no value");
      if (!step.fields.emplace(key, Field{value, line}).second) fail(line, "'" + key + "' is given twice");
      applyStepField(step, key, value, {file_, line});
    }
    fail(static_cast<int>(at), "the ```step block is not closed by ```");
  }

  // Reads a ```question block: `right:` or `wrong:` lines, each followed by a `because:` line (a line that
  // starts with spaces continues the one before); returns the index of the closing fence.
  std::size_t parseQuestionBlock(std::size_t at, Step& step) {
    std::string* last = nullptr;  // the entry a continuation line extends
    bool needsBecause = false;
    int choiceLine = 0;
    for (std::size_t i = at; i < lines_.size(); ++i) {
      const int line = static_cast<int>(i) + 1;
      const std::string& raw = lines_[i];
      const std::string t = trim(raw);
      if (t == "```") {
        if (needsBecause) fail(choiceLine, "this choice has no 'because:' line that explains it");
        int right = 0;
        for (const homework::Choice& c : step.choices) right += c.right;
        if (step.choices.size() < 2)
          fail(step.questionLine, "a ```question block needs at least two choices ('right:' and 'wrong:')");
        if (right != 1)
          fail(step.questionLine,
               "a ```question block needs exactly one 'right:' choice, not " + std::to_string(right));
        if (step.choices.size() > 6)
          fail(step.questionLine, "a ```question block offers at most six choices");
        return i;
      }
      if (t.empty()) continue;
      if (raw[0] == ' ' || raw[0] == '\t') {
        if (!last)
          fail(line,
               "a continuation line (it starts with spaces) needs a 'right:', 'wrong:' or "
               "'because:' line before it");
        *last += " " + t;
        continue;
      }
      const auto colon = t.find(':');
      const std::string key = colon == std::string::npos ? "" : trim(t.substr(0, colon));
      const std::string value = colon == std::string::npos ? "" : trim(t.substr(colon + 1));
      if (key != "right" && key != "wrong" && key != "because")
        fail(line,
             "expected 'right: ...', 'wrong: ...' or 'because: ...' in the question block, got '" + t + "'");
      if (value.empty()) fail(line, "'" + key + "' has no text");
      if (key == "because") {
        if (!needsBecause) fail(line, "'because:' explains the 'right:' or 'wrong:' line just before it");
        step.choices.back().because = value;
        last = &step.choices.back().because;
        needsBecause = false;
      } else {
        if (needsBecause) fail(choiceLine, "this choice has no 'because:' line that explains it");
        step.choices.push_back({value, "", key == "right"});
        last = &step.choices.back().text;
        needsBecause = true;
        choiceLine = line;
      }
    }
    fail(step.questionLine, "the ```question block is not closed by ```");
  }

  void finishStepBlock(Step& step) {
    stepBlockSeen_ = false;
    finishStep(step, file_);
  }

  void checkFigureNames() {
    std::map<std::string, int> files;
    for (const auto& step : lesson_.steps) {
      for (const auto& f : step.figureFiles()) {
        const int line = step.fields.at("figure").line;
        auto [it, fresh] = files.emplace(f, line);
        if (!fresh)
          fail(line, "figure file '" + f + "' is already used at line " + std::to_string(it->second));
      }
    }
  }

  void checkPlaceholders(const std::string& text, int firstLine) {
    for (const auto& ph : findPlaceholders(text, firstLine)) {
      if (!ph.error.empty()) fail(ph.line, ph.error);
    }
  }

  std::vector<std::string> lines_;
  std::string file_;
  Lesson lesson_;
  bool stepBlockSeen_ = false;
};

}  // namespace

const std::vector<std::string>& stepKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> names;
    for (const StepKey& k : stepKeyTable())
      if (k.name != "reflectance") names.push_back(k.name);
    return names;
  }();
  return keys;
}

const std::vector<std::string>& knownMethods() {
  static const std::vector<std::string> methods = declaredFormFactorMethods();  // the registry's names
  return methods;
}

const std::vector<std::string>& knownSolvers() {
  static const std::vector<std::string> solvers = solverNames();  // the registry's table
  return solvers;
}

Lesson parseLesson(const std::string& text, const std::string& id, const std::string& file) {
  return Parser(text, id, file).parse();
}

}  // namespace rt::lesson
