// VTK draws on one thread at a time in this process. A step's figures are drawn on the figure thread for the
// job that computed the step (their offscreen windows open X connections of their own), while the window's
// thread draws the 3D views and the exports; both reach VTK's text renderer, whose FreeType glyph cache is
// not safe to share between threads. Whoever renders holds this lock for the length of the frame or the
// figure (recursive: an export may paint a view while it holds it).
#pragma once

#include <mutex>

namespace rt::app {

inline std::recursive_mutex& renderMutex() {
  static std::recursive_mutex mutex;
  return mutex;
}

}  // namespace rt::app
