#include "lesson/lesson_parser.h"
#include "core/camera_path.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "core/formfactor/formfactor_method.h"
#include "core/input_error.h"
#include "core/solvers/solver.h"
#include "lesson/placeholders.h"
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

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
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
        if (step) finishStep(*step);
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
    if (step) finishStep(*step);
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
        fail(line,
             "unknown step key '" + key + "' (known: " + joined(stepKeys()) + ", reflectance.<surface>)");
      if (value.empty()) fail(line, "'" + key + "' has no value");
      if (!step.fields.emplace(key, Field{value, line}).second) fail(line, "'" + key + "' is given twice");
      applyField(step, key, value, {file_, line});
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

  // Parameters go through the table of step keys (step_keys.h); the keys that describe the step itself are
  // read here.
  void applyField(Step& step, const std::string& key, const std::string& value, const SourceLocation& where) {
    const StepKey* row = findStepKey(key);
    if (key == "scene") {
      step.scene = value;
    } else if (key == "stage") {
      auto s = stageFromString(value);
      if (!s) fail(where.line, "unknown stage '" + value + "' (known: " + joined(stageNames()) + ")");
      step.stage = *s;
    } else if (key == "export") {
      const auto dot = value.rfind('.');
      const std::string ext = dot == std::string::npos ? "" : value.substr(dot);
      if (ext != ".csv" && ext != ".mtx" && ext != ".npy" && ext != ".tex")
        fail(where.line, "export names a file ending in .csv, .mtx, .npy or .tex, not '" + value + "'");
      if (value.find('/') != std::string::npos) fail(where.line, "export is a file name, not a path");
      step.parameters.exportMatrix = value;
    } else if (key == "views") {
      for (const auto& v : parseList(value)) {
        auto view = viewFromString(v);
        if (!view) fail(where.line, "unknown view '" + v + "' (known: " + joined(viewNames()) + ")");
        if (std::find(step.views.begin(), step.views.end(), *view) != step.views.end())
          fail(where.line, "view '" + v + "' is listed twice");
        step.views.push_back(*view);
      }
    } else if (key == "camera.position") {
      step.camera.position = parseVec3(value, where, key);
    } else if (key == "camera.target") {
      step.camera.target = parseVec3(value, where, key);
    } else if (key == "camera.up") {
      step.camera.up = parseVec3(value, where, key);
    } else if (key == "camera.fov") {
      step.camera.fovYDegrees = parseDouble(value, where, key, row->min, row->max);
    } else if (key == "camera") {
      if (!isCameraName(value))
        fail(where.line, "camera names one of the scene's cameras, not '" + value + "'");
      step.camera.name = value;
    } else if (key == "camera-path") {
      step.camera.path = parseList(value);
      if (step.camera.path.size() < 2) fail(where.line, "camera-path names two cameras or more");
      for (const auto& name : step.camera.path)
        if (!isCameraName(name)) fail(where.line, "'" + name + "' is not a camera name");
    } else if (key == "path-frames") {
      step.camera.pathFrames =
          parseInt(value, where, key, static_cast<int>(row->min), static_cast<int>(row->max));
    } else if (key == "highlight") {
      step.highlights = parseList(value);
    } else if (key == "figure") {
      const bool ok = std::all_of(value.begin(), value.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
      });
      if (!ok)
        fail(where.line,
             "a figure name uses a-z, 0-9 and '-' only (it becomes a file name), not '" + value + "'");
      step.figure = value;
    } else if (key == "caption") {
      if (value.empty()) fail(where.line, "a caption needs text");
      step.caption = value;
      step.captionLine = where.line;
    } else if (key == "controls") {
      for (const auto& c : parseList(value)) {
        const StepKey* control = findStepKey(c);
        if (!control || !control->control) {
          std::vector<std::string> names;
          for (const StepKey& k : stepKeyTable())
            if (k.control) names.push_back(k.name);
          fail(where.line,
               "'" + c + "' cannot be a control (controls: " + joined(names) + ", reflectance.<surface>)");
        }
        step.controls.push_back(c);
      }
    } else {
      applyStepValue(step.parameters, *row, key, value, where);
    }
  }

  // Checks that go across keys, once the whole step block is known.
  void finishStep(Step& step) {
    stepBlockSeen_ = false;
    if (step.fields.empty())
      fail(step.line, "step '" + step.title + "' has no ```step block (it needs at least 'stage')");
    auto lineOf = [&](const std::string& key) {
      auto it = step.fields.find(key);
      return it == step.fields.end() ? step.line : it->second.line;
    };
    if (!step.fields.count("stage")) fail(step.line, "step '" + step.title + "' has no 'stage'");
    const StepParameters& p = step.parameters;
    if (step.questionLine && step.stage != Stage::Exercise)
      fail(step.questionLine, "a ```question block belongs to an exercise step ('stage: exercise')");
    if (step.stage == Stage::Text || step.stage == Stage::Exercise) {
      if (!step.views.empty())
        fail(lineOf("views"),
             "a " + toString(step.stage) + " step has no figures: remove 'views' or choose a stage");
      if (step.stage == Stage::Exercise && p.topic.empty() && step.choices.empty())
        fail(lineOf("stage"),
             "an exercise step needs a 'topic' (see `radiosity homework topics`) or a ```question block");
      if (step.stage == Stage::Exercise && !p.topic.empty() && !step.choices.empty())
        fail(step.questionLine, "an exercise step has a 'topic' or a ```question block, not both");
    } else if (step.stage == Stage::Radiometry) {
      if (!step.scene.empty())
        fail(lineOf("scene"),
             "stage 'radiometry' builds its own patch from 'patch-distance', 'patch-tilt' and 'patch-size': "
             "remove 'scene'");
    } else if (step.stage == Stage::Reflection) {
      if (step.scene.empty() &&
          std::find(step.views.begin(), step.views.end(), View::PhongLocal) != step.views.end())
        fail(lineOf("views"), "the view 'phong-local' lights a scene: add a 'scene'");
    } else if (step.scene.empty()) {
      fail(lineOf("stage"), "stage '" + toString(step.stage) + "' needs a 'scene'");
    }
    if (!step.views.empty() && step.figure.empty())
      fail(lineOf("views"), "a step with views needs a 'figure' name");
    if (step.views.empty() && !step.figure.empty()) fail(lineOf("figure"), "a figure needs 'views' to show");
    if (step.views.empty() && !step.caption.empty())
      fail(lineOf("caption"), "a caption needs a figure to caption");
    if (!step.caption.empty()) step.captionView = step.views.front();
    if (p.subdivide && p.maxEdge) fail(lineOf("max-edge"), "give either 'subdivide' or 'max-edge', not both");
    for (View v : step.views) {
      if (!stageOffersView(step.stage, v))
        fail(lineOf("views"),
             "view '" + toString(v) + "' cannot be shown by stage '" + toString(step.stage) + "'");
    }
    if (std::find(step.views.begin(), step.views.end(), View::Walkthrough) != step.views.end() &&
        step.camera.path.empty())
      fail(lineOf("views"),
           "the walkthrough view needs a 'camera-path' (two or more of the scene's cameras)");
    if (p.basis != "constant" && step.stage != Stage::Solve)
      fail(lineOf("basis"), "'basis: " + p.basis +
                                "' is solved by solve steps only (an elements step compares both "
                                "bases itself; the other stages solve one value per element)");
    if (step.stage == Stage::Compare && p.solvers.size() + p.methods.size() + p.subdivisions.size() < 2)
      fail(lineOf("stage"), "a compare step needs at least two 'solvers', 'methods' or 'subdivisions'");
    if (step.stage == Stage::Benchmark) {
      if (p.methods.empty()) fail(lineOf("stage"), "a benchmark step needs 'methods'");
      if (p.sweep.empty()) fail(lineOf("stage"), "a benchmark step needs a 'sweep' (resolutions or samples)");
      if (p.reference.empty()) fail(lineOf("stage"), "a benchmark step needs a 'reference' method");
    }
    if (step.stage == Stage::Exact && p.reference.empty())
      fail(lineOf("stage"), "an exact step needs a 'reference' method to measure errors against");
    if (!p.exportMatrix.empty() && step.stage != Stage::Matrix)
      fail(lineOf("export"), "'export' belongs to a matrix step");
    for (const auto& c : step.controls)
      if (c == "method" && step.stage == Stage::Text) fail(lineOf("controls"), "a text step has no controls");
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
