// Kept apart from the VTK code: Xlib's macros (None, Bool, Status, ...) clash with VTK's and Eigen's names.
#include "viz/display_check.h"

#include <X11/Xlib.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace rt::viz {

bool displayAvailable() {
  // The connection stays open for the life of the process on purpose: a server started without
  // -noreset (plain `xvfb-run`) resets when its last client disconnects, and VTK's window, opened
  // right after, would find it mid-reset and abort.
  static Display* const display = XOpenDisplay(nullptr);
  const bool available = display != nullptr;
  return available;
}

void requireDisplay() {
  if (displayAvailable()) return;
  const char* name = std::getenv("DISPLAY");
  const std::string which =
      name && *name ? std::string("DISPLAY=") + name + " does not answer" : "DISPLAY is not set";
  throw std::runtime_error(
      "cannot render: no X display (" + which +
      "). Images are drawn with OpenGL through X; without a screen, run the command under "
      "Xvfb: xvfb-run -a -s \"-screen 0 1920x1080x24\" radiosity ...");
}

}  // namespace rt::viz
