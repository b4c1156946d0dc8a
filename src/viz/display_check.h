// VTK on Debian renders through X (GLX): with no reachable X server it aborts the whole process inside
// vtkXOpenGLRenderWindow. Every offscreen window is made through this check first, so that a missing display
// is an error message with the fix, not a crash.
#pragma once

namespace rt::viz {

// True when an X display can be opened (DISPLAY set and the server answering). Checked once per process.
bool displayAvailable();

// Throws std::runtime_error explaining how to render without a screen when no display is available.
void requireDisplay();

}  // namespace rt::viz
