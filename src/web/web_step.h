// A lesson step in the web edition, read through the lesson layer's one table of step keys
// (lesson/step_keys.h) and its one mapping to the pipeline (lesson/step_settings.h), so that a page's
// widgets, the values they take and what a change computes are those of the app's parameter panel.
// A page holds a step as its parameters written as the lesson writes them ({"subdivide": "4", ...}) and
// builds one widget per control from controlRowsJson.
#pragma once

#include <string>
#include <vector>

#include "core/pipeline/pipeline_settings.h"
#include "lesson/lesson.h"

namespace rt::web {

// The settings a live step computes with: the step's mapping, and for a bounces step the solver that adds
// one bounce (one term of the Neumann series) per iteration, as many as the step's `bounces`.
PipelineSettings liveSettings(const lesson::StepParameters& parameters, lesson::Stage stage);

// Reads {"stage": "solve" | "bounces", "parameters": {key: text}} into `settings` (every iteration
// recorded). Returns "" or what is wrong, naming the key, in the words the app's panel refuses an edit with.
std::string readStep(const std::string& json, PipelineSettings& settings);

// What the web edition computes for a step: its bounces, or else a solve (of a step that shows F, the
// solution with that F).
lesson::Stage liveStage(const lesson::Step& step);

// The keys a live view offers: the step's own `controls` and the ones every live view has (form-factor
// method, solver, subdivision, seed, light), each only where the table marks it a control of the step's
// stage.
std::vector<std::string> liveControls(const lesson::Step& step);

// The rows of `keys` for a page's widgets, a JSON array of {name, type, label, tooltip, default, min, max,
// step, decimals, logScale, zeroText, choices}; the form-factor methods are those of this build's registry
// (as the app lists them). Unknown keys are left out.
std::string controlRowsJson(const std::vector<std::string>& keys);

// The step's parameter keys as written in its lesson, {key: text}, for readStep; with the form-factor method
// the step computes with when it names none (a hemicube step's own).
std::string stepParametersJson(const lesson::Step& step);

}  // namespace rt::web
