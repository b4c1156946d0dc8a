// Where the 3D view looks from when a scene does not say: a room is seen from inside, through its open side
// (a Cornell box as the model archives publish it has no front wall), else from the OBJ convention's front
// (looking along -z with +y up), framing the bounding box. And the standard views of the View menu (front,
// top, side), as ParaView and F3D offer them.
#pragma once

#include "core/scene.h"

namespace rt::app {

enum class StandardView { Front, Top, Side };

// The scene's own camera when the file gives one; otherwise a view through the open side of a room whose
// bounding box is walled on the other sides; otherwise the front view.
Camera sceneCamera(const Scene& scene);

// The side of the bounding box that no inward-facing patch covers (as an outward axis direction, e.g.
// (0, 0, 1) for an open front), or zero when every side is mostly covered or the scene is not a room.
Vec3 openSide(const Scene& scene);

// The scene's front, as a horizontal axis direction pointing from the scene towards the viewer: the side its
// own camera looks from, else the open side of a room, else the OBJ convention's front (+z). The Cornell
// box's camera stands at -z: its front is (0, 0, -1).
Vec3 frontDirection(const Scene& scene);

// Looking at the whole bounding box from the front, the top (the front at the bottom) or the right-hand side.
Camera standardCamera(const Scene& scene, StandardView view, double fovYDegrees = 40.0);

}  // namespace rt::app
