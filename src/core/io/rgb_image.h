// A floating-point RGB image and the two plain formats the core writes without an image library: PFM (the
// values themselves, linear, for measuring) and binary PPM (tone-mapped for looking at).
#pragma once

#include <string>
#include <vector>

#include "core/vec.h"

namespace rt {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;  // row-major, top row first

  RgbImage() = default;
  RgbImage(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, Rgb::Zero()) {}
  Rgb& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  const Rgb& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

// Little-endian PFM ("PF", bottom row first as the format says). Throws InputError naming the path when it
// cannot be written.
void writePfm(const RgbImage& image, const std::string& path);
RgbImage readPfm(const std::string& path);

// Binary PPM: each channel times `scale`, clamped to [0, 1], sRGB-encoded, 8 bits.
void writePpm(const RgbImage& image, double scale, const std::string& path);

// The exposure that maps the image's mean (over pixels and channels) to 18 % grey; 1 for a black image.
double middleGreyScale(const RgbImage& image);

// Root mean square over pixels and channels of a - b (same size).
double rmsDifference(const RgbImage& a, const RgbImage& b);

}  // namespace rt
