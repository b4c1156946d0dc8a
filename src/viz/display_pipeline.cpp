#include "viz/display_pipeline.h"

#include <stdexcept>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rt::viz {
namespace {

std::uint8_t quantise(double unit) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(unit, 0.0, 1.0) * 255.0));
}

}  // namespace

ToneMap toneMapFromName(const std::string& name) {
  if (name == "reinhard") return ToneMap::Reinhard;
  if (name == "linear") return ToneMap::LinearClamp;
  throw std::invalid_argument("unknown tone map '" + name + "' (known: linear, reinhard)");
}

double autoExposure(const RgbField& B, ToneMap toneMap, const RgbField* emission) {
  std::vector<double> brightness;
  brightness.reserve(static_cast<std::size_t>(B.rows()));
  for (Eigen::Index i = 0; i < B.rows(); ++i) {
    const bool emitter = emission && i < emission->rows() && emission->row(i).maxCoeff() > 0.0;
    const double value = B.row(i).maxCoeff();
    if (!emitter && std::isfinite(value) && value > 0.0) brightness.push_back(value);
  }
  if (brightness.empty())  // only emitters are lit (or nothing): expose for them
    for (Eigen::Index i = 0; i < B.rows(); ++i)
      if (const double value = B.row(i).maxCoeff(); std::isfinite(value) && value > 0.0)
        brightness.push_back(value);
  if (brightness.empty()) return 1.0;
  const auto rank = static_cast<std::ptrdiff_t>(0.9 * static_cast<double>(brightness.size() - 1));
  std::nth_element(brightness.begin(), brightness.begin() + rank, brightness.end());
  const double reference = brightness[static_cast<std::size_t>(rank)];
  // Reinhard maps x to x/(1+x): 2 -> 2/3, which keeps the percentile bright without pretending it is white.
  return (toneMap == ToneMap::Reinhard ? 2.0 : 1.0) / reference;
}

DisplaySettings displaySettingsFor(const ImageOptions& options, const RgbField& B, const RgbField* emission) {
  DisplaySettings settings;
  settings.toneMap = options.toneMap;
  settings.srgbGamma = options.srgbGamma;
  settings.exposure = options.exposure > 0.0 ? options.exposure : autoExposure(B, options.toneMap, emission);
  return settings;
}

double linearToSrgb(double linear) {
  const double x = std::clamp(linear, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

double displayChannel(double value, const DisplaySettings& settings) {
  double x = std::max(0.0, value * settings.exposure);
  if (!std::isfinite(x)) x = 1.0;
  x = settings.toneMap == ToneMap::Reinhard ? x / (1.0 + x) : std::min(x, 1.0);
  return settings.srgbGamma ? linearToSrgb(x) : x;
}

Rgb8 displayColour(const Rgb& value, const DisplaySettings& settings) {
  return {quantise(displayChannel(value[0], settings)), quantise(displayChannel(value[1], settings)),
          quantise(displayChannel(value[2], settings))};
}

Rgb8 albedoColour(const Rgb& value, bool srgbGamma) {
  Rgb8 out;
  for (int c = 0; c < 3; ++c)
    out[static_cast<std::size_t>(c)] = quantise(srgbGamma ? linearToSrgb(value[c]) : value[c]);
  return out;
}

}  // namespace rt::viz
