#include "viz/colour_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rt::viz {
namespace {

// Ten evenly spaced samples of each map (matplotlib's viridis and cividis, which are CC0), interpolated
// linearly in sRGB: at this density the interpolation error is below one 8-bit step in lightness.
constexpr unsigned kViridis[10] = {0x440154, 0x482878, 0x3e4989, 0x31688e, 0x26828e,
                                   0x1f9e89, 0x35b779, 0x6ece58, 0xb5de2b, 0xfde725};
constexpr unsigned kCividis[10] = {0x00224e, 0x123570, 0x3b496c, 0x575d6d, 0x707173,
                                   0x8a8678, 0xa59c74, 0xc3b369, 0xe1cc55, 0xfee838};
constexpr unsigned kOkabeIto[8] = {0xe69f00, 0x56b4e9, 0x009e73, 0xf0e442,
                                   0x0072b2, 0xd55e00, 0xcc79a7, 0x000000};

double channel(unsigned hex, int c) {
  return static_cast<double>((hex >> (16 - 8 * c)) & 0xffu) / 255.0;
}

}  // namespace

ColourMap colourMapFromName(const std::string& name) {
  if (name == "viridis") return ColourMap::Viridis;
  if (name == "cividis") return ColourMap::Cividis;
  if (name == "grey" || name == "gray") return ColourMap::Grey;
  throw std::invalid_argument("unknown colour map '" + name + "' (viridis, cividis, grey)");
}

std::string toString(ColourMap map) {
  switch (map) {
    case ColourMap::Viridis:
      return "viridis";
    case ColourMap::Cividis:
      return "cividis";
    case ColourMap::Grey:
      return "grey";
  }
  return "viridis";
}

std::array<double, 3> sampleColourMapUnit(ColourMap map, double t) {
  if (std::isnan(t)) return {0.6, 0.6, 0.6};
  t = std::clamp(t, 0.0, 1.0);
  if (map == ColourMap::Grey) return {0.1 + 0.85 * t, 0.1 + 0.85 * t, 0.1 + 0.85 * t};
  const unsigned* table = map == ColourMap::Cividis ? kCividis : kViridis;
  const double position = t * 9.0;
  const int lower = std::min(8, static_cast<int>(position));
  const double f = position - lower;
  std::array<double, 3> out;
  for (int c = 0; c < 3; ++c)
    out[static_cast<std::size_t>(c)] =
        (1.0 - f) * channel(table[lower], c) + f * channel(table[lower + 1], c);
  return out;
}

Rgb8 sampleColourMap(ColourMap map, double t) {
  const auto unit = sampleColourMapUnit(map, t);
  return {static_cast<std::uint8_t>(std::lround(unit[0] * 255)),
          static_cast<std::uint8_t>(std::lround(unit[1] * 255)),
          static_cast<std::uint8_t>(std::lround(unit[2] * 255))};
}

Rgb8 qualitativeColour(int index) {
  const unsigned hex = kOkabeIto[((index % 8) + 8) % 8];
  return {static_cast<std::uint8_t>(hex >> 16), static_cast<std::uint8_t>((hex >> 8) & 0xff),
          static_cast<std::uint8_t>(hex & 0xff)};
}

Rgb8 categoryColour(int index) {
  // 7 chromatic colours (black is kept for outlines) x 3 lightness levels; 7 and 3 are coprime with the
  // stride.
  const int i = ((index % 21) + 21) % 21;
  Rgb8 base = qualitativeColour((i * 3) % 7);
  const double mix = (i % 3) * 0.3;  // towards white
  for (auto& c : base) c = static_cast<std::uint8_t>(std::lround(c + mix * (255 - c)));
  return base;
}

}  // namespace rt::viz
