// A page's settings as JSON, read into the pipeline's settings. Keys (all optional): "subdivide" N,
// "maxEdge" L, "noSubdivide" true, "splitAtContacts" true (the mesh; none: the scene's default mesh),
// "method", "samples", "resolution", "ffTolerance" (the form factors), "solver", "tolerance",
// "iterations", "seed" (the solver), "reflectance" {surface: [r, g, b]} and "lightScale" (the reader's
// overrides). The same meanings as the options of `radiosity solve` of the same names.
#pragma once

#include <string>

#include "core/pipeline/pipeline_settings.h"
#include "core/scene.h"

namespace rt::web {

// Returns "" and fills `settings`, or the first problem found, naming the key.
std::string readSettings(const std::string& json, const Scene& scene, PipelineSettings& settings);
// The settings as such JSON, for a page to hand back to readSettings: the same run wherever it is read.
std::string settingsJson(const PipelineSettings& settings);

}  // namespace rt::web
