// Named cameras and paths between them: what `--camera NAME`, a lesson step's `camera: NAME` and its
// `camera-path` ask of a scene. A radiosity solution does not depend on the view, so one solve can be looked
// at from every camera of a path (the walkthrough of the classic radiosity demos).
#pragma once

#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/scene.h"

namespace rt {

// A name as a scene may give a camera: letters, digits, '-', '_' and '.' (no spaces, so that `--camera`
// tells a name from the text "position x y z ...").
bool isCameraName(const std::string& text);

// The scene's cameras' names, comma-separated ("none" when it has none), for error messages.
std::string cameraNameList(const Scene& scene);

// The camera `name` of the scene; InputError at `where` naming the unknown name and the known ones.
const Camera& namedCamera(const Scene& scene, const std::string& name, const SourceLocation& where);

// `--camera`'s text: a camera name of the scene, or "position x y z target x y z up x y z fov_y_degrees f"
// (parseCameraText). InputError at `where` otherwise.
Camera cameraFromText(const Scene& scene, const std::string& text, const SourceLocation& where);

// `frames` cameras (at least 2) along the keyframes, the first and last frames on the first and last key:
// positions, targets and up vectors move along Catmull-Rom splines through the keys (no kink at a key), the
// field of view linearly; the keys are spaced by the distance the eye travels, so its speed is even.
// One key gives `frames` copies of it.
std::vector<Camera> interpolateCameraPath(const std::vector<Camera>& keys, int frames);

}  // namespace rt
