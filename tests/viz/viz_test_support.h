// Shared by the viz tests: a small hand-built scene with plausible radiosity, and PNG checks (blank detection
// and the baseline comparison: mean absolute difference per channel, in 8-bit steps).
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/scene.h"

namespace rt::vizt {

// A unit room open at the front (+z): white floor, ceiling and back wall, red left and green right walls, a
// square light in the ceiling. Every patch faces inwards.
Scene openRoom();
// openRoom() with each patch split count × count.
Mesh openRoomMesh(int count);
// Radiosity that falls off with the distance to the light: smooth, positive, with colour from the
// reflectances.
RgbField syntheticRadiosity(const Mesh& mesh);

struct PngStats {
  int width = 0, height = 0;
  double mean[3] = {0, 0, 0};
  double stddev = 0;  // over all pixels and channels
};
// Reads a PNG (vtkPNGReader); throws std::runtime_error when unreadable.
PngStats pngStats(const std::string& path);
// The luminance (0-255, Rec. 709 weights) of every pixel, row by row from the top of the picture.
struct PngLuminance {
  int width = 0, height = 0;
  std::vector<double> values;
  double at(int x, int y) const { return values[static_cast<std::size_t>(y) * width + x]; }
};
PngLuminance pngLuminance(const std::string& path);
// Largest per-channel mean absolute difference between two PNGs; a negative value when the sizes differ.
double pngDifference(const std::string& a, const std::string& b);

// Compares `rendered` against tests/baselines/<name>. When RT_UPDATE_BASELINES is set in the environment the
// rendered image replaces the baseline. Returns the difference (negative: size mismatch or missing baseline).
double compareWithBaseline(const std::string& rendered, const std::string& name);

std::string readFile(const std::string& path);

}  // namespace rt::vizt
