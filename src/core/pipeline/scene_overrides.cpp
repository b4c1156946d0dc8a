#include "core/pipeline/scene_overrides.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"

namespace rt {

Scene applyOverrides(const Scene& scene, const std::map<std::string, Rgb>& reflectance, double lightScale) {
  Scene result = scene;
  for (const auto& entry : reflectance) {
    const std::string& surfaceName =
        entry.first;  // a plain name: clang 14 cannot capture a structured binding
    const Rgb& rho = entry.second;
    auto it = std::find_if(result.surfaces.begin(), result.surfaces.end(),
                           [&](const Surface& s) { return s.name == surfaceName; });
    if (it == result.surfaces.end())
      throw InputError({scene.sourceFile}, "the scene has no surface '" + surfaceName + "'");
    if (!rho.allFinite() || (rho < 0).any() || (rho >= 1).any())
      throw InputError({scene.sourceFile}, "reflectance of '" + surfaceName + "' must be in [0,1)");
    Material material = result.materials[it->material];
    material.name += "/" + surfaceName;
    material.reflectance = rho;
    result.materials.push_back(material);
    it->material = static_cast<int>(result.materials.size()) - 1;
  }
  if (lightScale != 1.0) {
    if (!(lightScale >= 0) || !std::isfinite(lightScale))
      throw InputError({scene.sourceFile}, "the light scale must be a number >= 0");
    for (Material& m : result.materials) m.emission *= lightScale;
  }
  return result;
}

}  // namespace rt
