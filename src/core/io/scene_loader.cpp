#include "core/io/scene_loader.h"

#include <algorithm>
#include <cctype>

namespace rt {

Scene loadScene(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  const std::size_t slash = path.find_last_of("/\\");
  std::string extension =
      dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : path.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".json") return loadSceneJson(path);
  if (extension == ".obj") return loadSceneObj(path);
  throw InputError({path},
                   "unknown scene format '" + extension +
                       "': expected a .json scene (docs/scene-format.md) or a Wavefront .obj with its .mtl");
}

}  // namespace rt
