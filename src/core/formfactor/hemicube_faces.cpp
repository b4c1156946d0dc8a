// The hemicube's five faces as pixel grids: their axes in the eye's frame, their sizes, and the delta form
// factor of every pixel (the exact form factor from the eye to the pixel's square), computed once per
// resolution and shared by every hemicube drawn at it.
#include "core/formfactor/hemicube.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "core/formfactor/analytic.h"

namespace rt {
namespace {

int heightOf(int resolution, HemicubeFace face) {
  return face == HemicubeFace::Top ? resolution : hemicubeSideRows(resolution);
}

std::vector<double> computeDeltas(int resolution, HemicubeFace face) {
  const HemicubeFaceAxes axes = hemicubeFaceAxes(face);
  const int width = resolution, height = heightOf(resolution, face);
  const double du = 2.0 / width, dv = (1.0 - axes.upMin) / height;
  std::vector<double> deltas(static_cast<std::size_t>(width) * height);
  const Vec3 eye = Vec3::Zero(), normal(0, 0, 1);
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      const double a0 = -1 + column * du, a1 = a0 + du;
      const double b0 = axes.upMin + row * dv, b1 = b0 + dv;
      auto corner = [&](double a, double b) { return Vec3(a * axes.across + b * axes.up + axes.forward); };
      const Polygon pixel = {corner(a0, b0), corner(a1, b0), corner(a1, b1), corner(a0, b1)};
      deltas[static_cast<std::size_t>(row) * width + column] =
          std::abs(lambertContourSum(eye, normal, pixel));
    }
  return deltas;
}

}  // namespace

HemicubeFaceAxes hemicubeFaceAxes(HemicubeFace face) {
  switch (face) {
    case HemicubeFace::Top:
      return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, -1};
    case HemicubeFace::PlusU:
      return {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}, 0};
    case HemicubeFace::PlusV:
      return {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}, 0};
    case HemicubeFace::MinusU:
      return {{0, -1, 0}, {0, 0, 1}, {-1, 0, 0}, 0};
    case HemicubeFace::MinusV:
      return {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}, 0};
  }
  return {};
}

double maxDeltaFormFactor(int resolution) {
  double largest = 0;
  for (int f = 0; f < 5; ++f)
    for (double v : deltaFormFactors(resolution, static_cast<HemicubeFace>(f)))
      largest = std::max(largest, v);
  return largest;
}

int hemicubeSideRows(int resolution) {
  return (resolution + 1) / 2;
}

const std::vector<double>& deltaFormFactors(int resolution, HemicubeFace face) {
  if (resolution < 2) throw std::invalid_argument("hemicube resolution must be at least 2");
  static std::mutex mutex;
  static std::map<int, std::array<std::unique_ptr<std::vector<double>>, 5>> cache;
  std::lock_guard lock(mutex);
  auto& entry = cache[resolution];
  auto& deltas = entry[static_cast<int>(face)];
  if (!deltas) deltas = std::make_unique<std::vector<double>>(computeDeltas(resolution, face));
  return *deltas;
}

}  // namespace rt
