// The reader's changes to a scene's materials: a surface's reflectance and the light's intensity. One
// function for the lessons, the app and the CLI, so that all three validate and apply them alike.
#pragma once

#include <map>
#include <string>

#include "core/scene.h"

namespace rt {

// The scene with `reflectance` (surface name -> rho, each channel in [0,1)) and every emission times
// `lightScale` (>= 0). A surface with its own reflectance gets its own copy of the material, so that surfaces
// sharing the old one keep theirs. Throws InputError naming the scene file and the surface at fault.
Scene applyOverrides(const Scene& scene, const std::map<std::string, Rgb>& reflectance, double lightScale);

}  // namespace rt
