// A scene compiled into the app: the Cornell box (geometry of the Cornell Program of Computer Graphics data,
// in metres, with RGB approximations of its reflectances). The app starts with it when no lesson or scene
// file is available, so that the first window is never empty.
#pragma once

#include "core/scene.h"

namespace rt::app {

Scene builtinCornellBox();

}  // namespace rt::app
