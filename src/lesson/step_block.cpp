#include "lesson/step_block.h"

#include <algorithm>

#include "core/camera_path.h"
#include "lesson/step_keys.h"
#include "lesson/value_parsing.h"

namespace rt::lesson {
namespace {

[[noreturn]] void failAt(const SourceLocation& where, const std::string& message) {
  throw InputError(where, message);
}

[[noreturn]] void fail(const std::string& file, int line, const std::string& message) {
  throw InputError({file, line}, message);
}

}  // namespace

// Parameters go through the table of step keys (step_keys.h); the keys that describe the step itself are
// read here.
void applyStepField(Step& step, const std::string& key, const std::string& value,
                    const SourceLocation& where) {
  const StepKey* row = findStepKey(key);
  if (key == "scene") {
    step.scene = value;
  } else if (key == "stage") {
    auto s = stageFromString(value);
    if (!s) failAt(where, "unknown stage '" + value + "' (known: " + joinedNames(stageNames()) + ")");
    step.stage = *s;
  } else if (key == "export") {
    const auto dot = value.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : value.substr(dot);
    if (ext != ".csv" && ext != ".mtx" && ext != ".npy" && ext != ".tex")
      failAt(where, "export names a file ending in .csv, .mtx, .npy or .tex, not '" + value + "'");
    if (value.find('/') != std::string::npos) failAt(where, "export is a file name, not a path");
    step.parameters.exportMatrix = value;
  } else if (key == "views") {
    for (const auto& v : parseList(value)) {
      auto view = viewFromString(v);
      if (!view) failAt(where, "unknown view '" + v + "' (known: " + joinedNames(viewNames()) + ")");
      if (std::find(step.views.begin(), step.views.end(), *view) != step.views.end())
        failAt(where, "view '" + v + "' is listed twice");
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
    if (!isCameraName(value)) failAt(where, "camera names one of the scene's cameras, not '" + value + "'");
    step.camera.name = value;
  } else if (key == "camera-path") {
    step.camera.path = parseList(value);
    if (step.camera.path.size() < 2) failAt(where, "camera-path names two cameras or more");
    for (const auto& name : step.camera.path)
      if (!isCameraName(name)) failAt(where, "'" + name + "' is not a camera name");
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
      failAt(where, "a figure name uses a-z, 0-9 and '-' only (it becomes a file name), not '" + value + "'");
    step.figure = value;
  } else if (key == "caption") {
    if (value.empty()) failAt(where, "a caption needs text");
    step.caption = value;
    step.captionLine = where.line;
  } else if (key == "controls") {
    for (const auto& c : parseList(value)) {
      const StepKey* control = findStepKey(c);
      if (!control || !control->control) {
        std::vector<std::string> names;
        for (const StepKey& k : stepKeyTable())
          if (k.control) names.push_back(k.name);
        failAt(where, "'" + c + "' cannot be a control (controls: " + joinedNames(names) +
                          ", reflectance.<surface>)");
      }
      step.controls.push_back(c);
    }
  } else {
    applyStepValue(step.parameters, *row, key, value, where);
  }
}

// Checks that go across keys, once the whole step block is known.
void finishStep(Step& step, const std::string& file) {
  if (step.fields.empty())
    fail(file, step.line, "step '" + step.title + "' has no ```step block (it needs at least 'stage')");
  auto lineOf = [&](const std::string& key) {
    auto it = step.fields.find(key);
    return it == step.fields.end() ? step.line : it->second.line;
  };
  if (!step.fields.count("stage")) fail(file, step.line, "step '" + step.title + "' has no 'stage'");
  const StepParameters& p = step.parameters;
  if (step.questionLine && step.stage != Stage::Exercise)
    fail(file, step.questionLine, "a ```question block belongs to an exercise step ('stage: exercise')");
  if (step.stage == Stage::Text || step.stage == Stage::Exercise) {
    if (!step.views.empty())
      fail(file, lineOf("views"),
           "a " + toString(step.stage) + " step has no figures: remove 'views' or choose a stage");
    if (step.stage == Stage::Exercise && p.topic.empty() && step.choices.empty())
      fail(file, lineOf("stage"),
           "an exercise step needs a 'topic' (see `radiosity homework topics`) or a ```question block");
    if (step.stage == Stage::Exercise && !p.topic.empty() && !step.choices.empty())
      fail(file, step.questionLine, "an exercise step has a 'topic' or a ```question block, not both");
  } else if (step.stage == Stage::Radiometry) {
    if (!step.scene.empty())
      fail(file, lineOf("scene"),
           "stage 'radiometry' builds its own patch from 'patch-distance', 'patch-tilt' and 'patch-size': "
           "remove 'scene'");
  } else if (step.stage == Stage::Reflection) {
    if (step.scene.empty() &&
        std::find(step.views.begin(), step.views.end(), View::PhongLocal) != step.views.end())
      fail(file, lineOf("views"), "the view 'phong-local' lights a scene: add a 'scene'");
  } else if (step.scene.empty()) {
    fail(file, lineOf("stage"), "stage '" + toString(step.stage) + "' needs a 'scene'");
  }
  if (!step.views.empty() && step.figure.empty())
    fail(file, lineOf("views"), "a step with views needs a 'figure' name");
  if (step.views.empty() && !step.figure.empty())
    fail(file, lineOf("figure"), "a figure needs 'views' to show");
  if (step.views.empty() && !step.caption.empty())
    fail(file, lineOf("caption"), "a caption needs a figure to caption");
  if (!step.caption.empty()) step.captionView = step.views.front();
  if (p.subdivide && p.maxEdge)
    fail(file, lineOf("max-edge"), "give either 'subdivide' or 'max-edge', not both");
  for (View v : step.views) {
    if (!stageOffersView(step.stage, v))
      fail(file, lineOf("views"),
           "view '" + toString(v) + "' cannot be shown by stage '" + toString(step.stage) + "'");
  }
  if (std::find(step.views.begin(), step.views.end(), View::Walkthrough) != step.views.end() &&
      step.camera.path.empty())
    fail(file, lineOf("views"),
         "the walkthrough view needs a 'camera-path' (two or more of the scene's cameras)");
  if (p.basis != "constant" && step.stage != Stage::Solve)
    fail(file, lineOf("basis"),
         "'basis: " + p.basis +
             "' is solved by solve steps only (an elements step compares both "
             "bases itself; the other stages solve one value per element)");
  if (step.stage == Stage::Compare && p.solvers.size() + p.methods.size() + p.subdivisions.size() < 2)
    fail(file, lineOf("stage"), "a compare step needs at least two 'solvers', 'methods' or 'subdivisions'");
  if (step.stage == Stage::Benchmark) {
    if (p.methods.empty()) fail(file, lineOf("stage"), "a benchmark step needs 'methods'");
    if (p.sweep.empty())
      fail(file, lineOf("stage"), "a benchmark step needs a 'sweep' (resolutions or samples)");
    if (p.reference.empty()) fail(file, lineOf("stage"), "a benchmark step needs a 'reference' method");
  }
  if (step.stage == Stage::Exact && p.reference.empty())
    fail(file, lineOf("stage"), "an exact step needs a 'reference' method to measure errors against");
  if (!p.exportMatrix.empty() && step.stage != Stage::Matrix)
    fail(file, lineOf("export"), "'export' belongs to a matrix step");
  for (const auto& c : step.controls)
    if (c == "method" && step.stage == Stage::Text)
      fail(file, lineOf("controls"), "a text step has no controls");
}

}  // namespace rt::lesson
