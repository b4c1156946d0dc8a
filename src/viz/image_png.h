// A linear RGB image (W/m^2) written as an 8-bit PNG at one exposure: what the core's PFM holds for
// measuring, made into a picture for looking at. vtkPNGWriter only: no X server is needed.
#pragma once

#include <string>

#include "core/io/rgb_image.h"

namespace rt::viz {

// Each channel times `scale`, clamped to [0, 1] and sRGB-encoded, as writePpm does. Throws std::runtime_error
// naming the path when it cannot be written.
void writeRgbImagePng(const RgbImage& image, double scale, const std::string& path);

}  // namespace rt::viz
