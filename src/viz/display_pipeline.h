// The display pipeline that turns radiosity (W/m^2, unbounded, linear) into 8-bit sRGB: exposure, tone
// mapping, gamma. Pure functions without VTK, shared by every view that shows light (scene images, the app's
// 3D view).
#pragma once

#include <string>

#include <array>
#include <cstdint>

#include "core/vec.h"
#include "viz/scene_image.h"

namespace rt::viz {

using Rgb8 = std::array<std::uint8_t, 3>;

struct DisplaySettings {
  double exposure = 1.0;  // multiplier applied to B before the tone map (already resolved: never 0 here)
  ToneMap toneMap = ToneMap::LinearClamp;
  bool srgbGamma = true;
};

// Automatic exposure: the value that maps a bright but typical element (the 90th percentile of the
// per-element maximum channel, emitters excluded when something else is lit) to display white (linear clamp)
// or to 2/3 of it (Reinhard). Emitters are usually orders of magnitude brighter than everything they light;
// letting them set the exposure would show a black room.
// The tone map a lesson or an option names ("linear" or "reinhard"; step_keys.cpp lists them).
ToneMap toneMapFromName(const std::string& name);

double autoExposure(const RgbField& B, ToneMap toneMap, const RgbField* emission = nullptr);
// Resolves ImageOptions::exposure (0 = automatic).
DisplaySettings displaySettingsFor(const ImageOptions& options, const RgbField& B,
                                   const RgbField* emission = nullptr);

// Linear [0,1] -> sRGB-encoded [0,1] (IEC 61966-2-1 piecewise curve).
double linearToSrgb(double linear);
// One channel through exposure, tone map and gamma, in [0,1].
double displayChannel(double value, const DisplaySettings& settings);
Rgb8 displayColour(const Rgb& value, const DisplaySettings& settings);
// Reflectance-like quantities already in [0,1]: only gamma (when enabled) and quantisation.
Rgb8 albedoColour(const Rgb& value, bool srgbGamma = true);

}  // namespace rt::viz
