// Loading scenes: the project's JSON format (docs/scene-format.md) and Wavefront OBJ/MTL (Kd = reflectance,
// Ke = emission, one face = one patch). Every loader validates what it reads and throws InputError naming the
// file and the line or JSON path; non-planar and concave polygons are split into triangles, and lights that
// can reach nothing are reported, with warnings in Scene::warnings.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/input_error.h"
#include "core/scene.h"

namespace rt {

// Chooses the format by extension (.json, .obj). Throws InputError for unknown extensions and unreadable
// files.
Scene loadScene(const std::string& path);
Scene loadSceneJson(const std::string& path);
// From text (tests, lessons); `fileName` is only used in messages.
Scene parseSceneJson(const std::string& text, const std::string& fileName = "<json>");
Scene loadSceneObj(const std::string& path);
// From text: `mtlText` gives the text of each material library the OBJ names (the path as the OBJ's folder +
// the mtllib name), or nullopt when it cannot be read. Tests and fuzzing use it.
using MtlSource = std::function<std::optional<std::string>(const std::string& path)>;
Scene parseSceneObj(const std::string& text, const std::string& fileName, const MtlSource& mtlText);

// A camera as text, "position x y z target x y z up x y z fov_y_degrees f" (any order, every word once): the
// OBJ files' camera comment and the programs' --camera. Throws InputError at `where` naming what is wrong.
Camera parseCameraText(const std::string& text, const SourceLocation& where);

// Checks the invariants every loader guarantees (convex planar non-degenerate patches, finite coordinates,
// reflectance in [0,1), emission >= 0 and finite). Throws InputError naming the patch's origin.
void validateScene(const Scene& scene);

// A solve needs a light; form factors do not, so loading does not ask for one. Throws InputError naming the
// scene file when no patch emits.
void requireLight(const Scene& scene);

}  // namespace rt
