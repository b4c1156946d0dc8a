#include "web/web_step.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/formfactor/formfactor_method.h"
#include "core/input_error.h"
#include "lesson/step_keys.h"
#include "lesson/step_settings.h"

namespace rt::web {
namespace {

using Json = nlohmann::json;

// A key whose value the step's parameters hold (not one that describes the step, such as `scene`).
const lesson::StepKey* parameterKey(const std::string& name) {
  const lesson::StepKey* row = lesson::findStepKey(name);
  if (!row) return nullptr;
  if (row->name != "reflectance" && std::holds_alternative<std::monostate>(row->slot)) return nullptr;
  return row;
}

std::string typeName(lesson::KeyType type) {
  switch (type) {
    case lesson::KeyType::Int:
      return "int";
    case lesson::KeyType::Double:
      return "double";
    case lesson::KeyType::Bool:
      return "bool";
    case lesson::KeyType::Choice:
      return "choice";
    case lesson::KeyType::Rgb:
      return "rgb";
    default:
      return "text";
  }
}

}  // namespace

PipelineSettings liveSettings(const lesson::StepParameters& parameters, lesson::Stage stage) {
  PipelineSettings settings = lesson::settingsFor(parameters, parameters.method);
  settings.recordHistory = true;
  if (stage == lesson::Stage::Bounces) {
    settings.solver = "bounces";
    settings.solverOptions.maxIterations = parameters.bounces;
    settings.solverOptions.tolerance = 1e-15;
  }
  return settings;
}

std::string readStep(const std::string& text, PipelineSettings& settings) {
  const Json json = Json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) return "step: not a JSON object";
  lesson::Stage stage = lesson::Stage::Solve;
  if (json.contains("stage")) {
    const auto named =
        json["stage"].is_string() ? lesson::stageFromString(json["stage"].get<std::string>()) : std::nullopt;
    if (!named || (*named != lesson::Stage::Solve && *named != lesson::Stage::Bounces))
      return "step: \"stage\" is " + json["stage"].dump() +
             ": the web edition computes solve and bounces steps";
    stage = *named;
  }
  const Json parameters = json.value("parameters", Json::object());
  if (!parameters.is_object()) return "step: \"parameters\" must map step keys to their values";
  lesson::StepParameters p;
  for (const auto& item : parameters.items()) {
    const lesson::StepKey* row = parameterKey(item.key());
    if (!row) return "step: \"" + item.key() + "\" is not a parameter of a step";
    const Json& value = item.value();
    const std::string written = value.is_string() ? value.get<std::string>() : value.dump();
    try {
      lesson::applyStepValue(p, *row, item.key(), written, SourceLocation{});
    } catch (const InputError& e) {
      return e.message();
    }
  }
  if (p.subdivide && p.maxEdge) return "give either 'subdivide' or 'max-edge', not both";
  settings = liveSettings(p, stage);
  return "";
}

lesson::Stage liveStage(const lesson::Step& step) {
  return step.stage == lesson::Stage::Bounces ? lesson::Stage::Bounces : lesson::Stage::Solve;
}

std::vector<std::string> liveControls(const lesson::Step& step) {
  std::vector<std::string> keys{"method", "solver", "subdivide", "seed", "light-scale"};
  for (const std::string& c : step.controls)
    keys.push_back(c.rfind("reflectance", 0) == 0 ? "reflectance" : c);
  keys.push_back("reflectance");
  std::vector<std::string> out;
  for (const std::string& key : keys) {
    const lesson::StepKey* row = parameterKey(key);
    if (!row || !row->control || !row->acceptedBy(liveStage(step))) continue;
    if (std::find(out.begin(), out.end(), row->name) == out.end()) out.push_back(row->name);
  }
  return out;
}

std::string controlRowsJson(const std::vector<std::string>& keys) {
  Json rows = Json::array();
  for (const std::string& key : keys) {
    const lesson::StepKey* row = lesson::findStepKey(key);
    if (!row) continue;
    Json r{{"name", row->name},         {"type", typeName(row->type)}, {"label", row->label},
           {"tooltip", row->tooltip},   {"default", row->defaultText}, {"min", row->min},
           {"max", row->max},           {"step", row->step},           {"decimals", row->decimals},
           {"logScale", row->logScale}, {"zeroText", row->zeroText}};
    if (row->type == lesson::KeyType::Choice)
      r["choices"] = row->name == "method" ? formFactorMethodNames() : row->allowed();
    rows.push_back(r);
  }
  return rows.dump();
}

std::string stepParametersJson(const lesson::Step& step) {
  Json out = Json::object();
  for (const auto& [key, field] : step.fields)
    if (parameterKey(key)) out[key] = field.value;
  if (!out.contains("method") && lesson::methodOf(step) != step.parameters.method)
    out["method"] = lesson::methodOf(step);
  return out.dump();
}

}  // namespace rt::web
