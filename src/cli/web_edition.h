// `radiosity book --web`: the HTML book's figures made live. Beside the pages go the WebAssembly core
// (radiosity-core.js), three.js (Debian's libjs-three) and the page script (src/web/page); every step that
// solves a scene and shows it in 3D gets a live view under its figure, computed in the browser from the
// step's scene and settings (<lesson>-live.js). Nothing is fetched at run time: the site works from file://
// and from any static server.
#pragma once

#include <string>
#include <vector>

#include "lesson/book.h"
#include "lesson/lesson_loader.h"

namespace rt::cli {

struct WebAssets {
  std::string module;     // radiosity-core.js, the wasm preset's build
  std::string three;      // libjs-three's folder: three.min.js, examples/js/controls/OrbitControls.js
  std::string pageFiles;  // src/web/page: live_worker.js, live_view.js, live_view.css, playground.js
};

// Where this build found them (their absence is reported by writeWebEdition, with what to do).
WebAssets defaultWebAssets();

// Copies the assets to <output>/web/ and rewrites the lessons' pages there with their live views. Returns
// how many live views the pages got. Throws std::runtime_error naming a missing asset.
int writeWebEdition(const std::string& output, const std::vector<lesson::RenderedLesson>& rendered,
                    const std::vector<std::string>& files, const lesson::LessonFolders& folders,
                    const WebAssets& assets);

}  // namespace rt::cli
