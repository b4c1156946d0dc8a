// Offscreen images of a solved scene (VTK, needs an X server: run under xvfb-run). Public header: no VTK
// types.
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/scene.h"

namespace rt::viz {

enum class ToneMap { LinearClamp, Reinhard };

struct ImageOptions {
  int width = 1024;
  int height = 1024;
  double exposure =
      0.0;  // multiplier on radiosity before tone mapping; 0 = automatic (from the scene's values)
  ToneMap toneMap = ToneMap::LinearClamp;
  bool srgbGamma = true;
  bool smooth = false;     // per-vertex interpolated radiosity instead of flat per element
  bool showEdges = false;  // mesh edges
};

// Renders the elements coloured by B (n x 3, W/m^2) through the display pipeline (exposure, tone map, gamma)
// from the camera and writes a PNG. Throws std::runtime_error naming the path if it cannot be written.
void renderRadiosityImage(const Mesh& mesh, const RgbField& B, const Camera& camera,
                          const ImageOptions& options, const std::string& pngPath);
// The same for a linear basis: `corners` its values at every element corner (SceneViewData::corners).
void renderRadiosityImage(const Mesh& mesh, const RgbField& B, const RgbField& corners, const Camera& camera,
                          const ImageOptions& options, const std::string& pngPath);

}  // namespace rt::viz
