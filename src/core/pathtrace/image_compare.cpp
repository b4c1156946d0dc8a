#include "core/pathtrace/image_compare.h"

#include <algorithm>
#include <cmath>

#include "core/formfactor/sampling.h"
#include "core/parallel.h"

namespace rt {

RgbImage renderElements(const Mesh& mesh, const RgbField& B, const RayScene& rays, const Camera& camera,
                        int width, int height, int samples) {
  RgbImage image(width, height);
  const StrataGrid grid(std::max(1, samples));
  parallelForChunks(0, static_cast<std::size_t>(height), {}, [&](std::size_t lo, std::size_t hi) {
    for (int y = static_cast<int>(lo); y != static_cast<int>(hi); ++y)
      for (int x = 0; x < width; ++x) {
        PairRandom random(7, static_cast<std::uint64_t>(y) * width + x, 0);
        Rgb sum = Rgb::Zero();
        for (int k = 0; k < std::max(1, samples); ++k) {
          const Vec2 jitter = grid.sample(k, random);
          const RayHit hit = rays.firstHit(
              camera.position, cameraRay(camera, width, height, x + jitter.x(), y + jitter.y()), -1);
          if (hit.element >= 0 && hit.frontSide) sum += B.row(hit.element).transpose().array();
        }
        image.at(x, y) = sum / std::max(1, samples);
      }
  });
  return image;
}

ImageError compareToReference(const RgbImage& image, const TracedImage& reference) {
  ImageError out;
  const std::size_t n = image.pixels.size();
  if (n == 0 || reference.B.pixels.size() != n) return out;
  double mean = 0, squares = 0, noise = 0;
  for (std::size_t k = 0; k < n; ++k) mean += reference.B.pixels[k].sum() / 3;
  mean /= static_cast<double>(n);
  if (!(mean > 0)) return out;
  // Per pixel: d^2 - sigma^2 is an unbiased estimate of the image's own squared error there (the reference's
  // noise is independent of the image). Their mean estimates the mean squared error, their spread its
  // uncertainty.
  double sum = 0, sumSquares = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double d2 = (image.pixels[k] - reference.B.pixels[k]).square().sum() / 3;
    const double s2 = reference.error.pixels[k].square().sum() / 3;
    squares += d2;
    noise += s2;
    sum += d2 - s2;
    sumSquares += (d2 - s2) * (d2 - s2);
  }
  const double count = static_cast<double>(n);
  out.rmsDifference = std::sqrt(squares / count) / mean;
  out.referenceNoise = std::sqrt(noise / count) / mean;
  const double meanSquare = sum / count;
  const double spread = std::sqrt(std::max(0.0, sumSquares / count - meanSquare * meanSquare) / count);
  out.error = std::sqrt(std::max(0.0, meanSquare)) / mean;
  out.low = std::sqrt(std::max(0.0, meanSquare - 1.96 * spread)) / mean;
  out.high = std::sqrt(std::max(0.0, meanSquare + 1.96 * spread)) / mean;
  return out;
}

RgbImage absoluteDifference(const RgbImage& a, const RgbImage& b) {
  RgbImage out(a.width, a.height);
  for (std::size_t k = 0; k < a.pixels.size() && k < b.pixels.size(); ++k)
    out.pixels[k] = (a.pixels[k] - b.pixels[k]).abs();
  return out;
}

RgbImage greyOfLargestChannel(const RgbImage& image, double full) {
  RgbImage out(image.width, image.height);
  for (std::size_t k = 0; k < image.pixels.size(); ++k)
    out.pixels[k] = Rgb::Constant(full > 0 ? std::min(1.0, image.pixels[k].maxCoeff() / full) : 0.0);
  return out;
}

}  // namespace rt
