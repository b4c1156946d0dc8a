#include "core/io/rgb_image.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "core/input_error.h"

namespace rt {

void writePfm(const RgbImage& image, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError({path}, "cannot write the image");
  // A negative scale says little-endian.
  out << "PF\n" << image.width << " " << image.height << "\n-1.0\n";
  std::vector<float> row(static_cast<std::size_t>(image.width) * 3);
  for (int y = image.height - 1; y >= 0; --y) {
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        row[static_cast<std::size_t>(3 * x + c)] = static_cast<float>(image.at(x, y)(c));
    static_assert(std::endian::native == std::endian::little, "PFM is written little-endian");
    out.write(reinterpret_cast<const char*>(row.data()),
              static_cast<std::streamsize>(row.size() * sizeof(float)));
  }
  if (!out) throw InputError({path}, "error while writing the image");
}

RgbImage readPfm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path}, "cannot open the image");
  std::string magic;
  int width = 0, height = 0;
  double scale = 0;
  in >> magic >> width >> height >> scale;
  if (magic != "PF" || width <= 0 || height <= 0 || scale >= 0 || width > 1 << 16 || height > 1 << 16)
    throw InputError({path, 1}, "not a little-endian colour PFM image");
  in.get();  // the single white space after the header
  RgbImage image(width, height);
  std::vector<float> row(static_cast<std::size_t>(width) * 3);
  for (int y = height - 1; y >= 0; --y) {
    in.read(reinterpret_cast<char*>(row.data()), static_cast<std::streamsize>(row.size() * sizeof(float)));
    if (!in) throw InputError({path}, "the image ends early");
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y)(c) = row[static_cast<std::size_t>(3 * x + c)];
  }
  return image;
}

void writePpm(const RgbImage& image, double scale, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError({path}, "cannot write the image");
  out << "P6\n" << image.width << " " << image.height << "\n255\n";
  for (const Rgb& p : image.pixels)
    for (int c = 0; c < 3; ++c) {
      const double v = std::clamp(p(c) * scale, 0.0, 1.0);
      const double srgb = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
      out.put(static_cast<char>(static_cast<unsigned char>(std::lround(255 * srgb))));
    }
  if (!out) throw InputError({path}, "error while writing the image");
}

double rmsDifference(const RgbImage& a, const RgbImage& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("images of different sizes");
  double sum = 0;
  for (std::size_t k = 0; k < a.pixels.size(); ++k) sum += (a.pixels[k] - b.pixels[k]).square().sum();
  return a.pixels.empty() ? 0.0 : std::sqrt(sum / (3.0 * static_cast<double>(a.pixels.size())));
}

double middleGreyScale(const RgbImage& image) {
  double mean = 0;
  for (const Rgb& p : image.pixels) mean += p.sum() / 3;
  mean /= static_cast<double>(std::max<std::size_t>(1, image.pixels.size()));
  return mean > 0 ? 0.18 / mean : 1.0;
}

}  // namespace rt
