// The one thread that draws the steps' figures. The computations run on a thread of their own each, which
// ends with them; drawn there, every figure would open a new offscreen window and compile its shaders again
// in its first frame (a tenth of a second and more for a 3D figure in a software renderer). This thread
// lives as long as the program and keeps its window from one figure to the next
// (viz::keepOffscreenWindowsOnThisThread).
#pragma once

#include <functional>

namespace rt::app {

// Runs `draw` on the figure thread and returns when it is done, throwing what it threw. Called from any
// thread, one caller at a time drawing (the callers hold renderMutex()).
void onFigureThread(const std::function<void()>& draw);

}  // namespace rt::app
