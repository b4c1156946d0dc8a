// The two-pass picture. A pixel's H has two parts of very different character: the emitters' direct light,
// with sharp shadow edges, and the gathered rest, which varies slowly along a surface. The direct part is
// computed exactly at every pixel (no rays where nothing can block, the hidden part cut out where something
// can); the gathered part, which costs hundreds of rays per point, is gathered only at the pixels of a grid,
// every `spacing`-th of each row and column, and interpolated between grid pixels that lie on the same patch
// and near the pixel in the scene. A pixel with no such grid pixel around it (a thin sliver of a patch, an
// edge) gathers for itself. A 1024 x 1024 picture at spacing 8 then gathers at 17k points instead of 1M.

#include <cmath>

#include "core/parallel.h"
#include "core/pathtrace/path_tracer.h"
#include "core/pathtrace/two_pass.h"

namespace rt {
namespace {

struct PixelHit {
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  int element = -1;  // of the tracing mesh; -1: nothing, or the back of a polygon
  double depth = 0;  // distance from the eye
};

}  // namespace

RgbImage TwoPass::render(const Camera& camera, int width, int height, const TwoPassOptions& options,
                         int gatherSpacing) const {
  const int spacing = std::max(1, gatherSpacing);
  std::vector<PixelHit> hits(static_cast<std::size_t>(width) * height);
  parallelFor(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const Vec3 direction = cameraRay(camera, width, height, x + 0.5, y + 0.5);
      const RayHit hit = tracing_.rays().firstHit(camera.position, direction, -1);
      if (hit.element < 0 || !hit.frontSide) continue;
      PixelHit& p = hits[static_cast<std::size_t>(y) * width + x];
      p.position = camera.position + hit.distance * direction;
      p.normal = tracing_.mesh().elements[static_cast<std::size_t>(hit.element)].normal;
      p.element = hit.element;
      p.depth = hit.distance;
    }
  });
  auto patchAt = [&](const PixelHit& p) { return p.element < 0 ? -1 : tracing_.patchOf(p.element); };
  auto gatherAt = [&](const PixelHit& p, std::uint64_t index, int rays) {
    TwoPassOptions o = options;
    o.gatherRays = rays;
    Rgb error;
    return gather({p.position, p.normal}, p.element, o, index, error);
  };

  // The grid: pixel (i * spacing, j * spacing), the last row and column clamped to the image's edge.
  const int gw = (width - 1 + spacing - 1) / spacing + 1, gh = (height - 1 + spacing - 1) / spacing + 1;
  auto gridX = [&](int i) { return std::min(i * spacing, width - 1); };
  auto gridY = [&](int j) { return std::min(j * spacing, height - 1); };
  std::vector<Rgb> gathered(static_cast<std::size_t>(gw) * gh, Rgb::Zero());
  if (spacing > 1)
    parallelFor(0, gh, [&](int j) {
      for (int i = 0; i < gw; ++i) {
        const PixelHit& p = hits[static_cast<std::size_t>(gridY(j)) * width + gridX(i)];
        if (p.element >= 0)
          gathered[static_cast<std::size_t>(j) * gw + i] =
              gatherAt(p, static_cast<std::uint64_t>(j) * gw + i, options.gatherRays);
      }
    });

  // How far apart in the scene two grid pixels `spacing` apart may lie at depth d and still be on one stretch
  // of surface: a few times what `spacing` pixels span there, so that a surface seen edge-on or a patch seen
  // on both sides of a block is not bridged.
  const double pixelAngle = 2 * std::tan(0.5 * camera.fovYDegrees * M_PI / 180) / height;
  const std::uint64_t ownIndex = static_cast<std::uint64_t>(gw) * gh;

  RgbImage image(width, height);
  parallelFor(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
      const PixelHit& p = hits[pixel];
      if (p.element < 0) continue;
      Rgb error;
      const Rgb direct = this->direct({p.position, p.normal}, p.element, options, pixel, error);
      Rgb indirect = Rgb::Zero();
      if (spacing == 1) {
        indirect = gatherAt(p, pixel, options.gatherRays);
      } else {
        const int patch = patchAt(p);
        const double reach = 4 * spacing * pixelAngle * p.depth;
        // Bilinear weights over the grid cell's corners, then, if none of them will do, inverse distance over
        // the ring of cells around it.
        Rgb sum = Rgb::Zero();
        double weights = 0;
        auto consider = [&](int i, int j, double w) {
          if (i < 0 || j < 0 || i >= gw || j >= gh) return;
          const PixelHit& g = hits[static_cast<std::size_t>(gridY(j)) * width + gridX(i)];
          if (patchAt(g) != patch || (g.position - p.position).norm() > reach) return;
          sum += w * gathered[static_cast<std::size_t>(j) * gw + i];
          weights += w;
        };
        const int i0 = x / spacing, j0 = y / spacing;
        const double fx = static_cast<double>(x - gridX(i0)) / std::max(1, gridX(i0 + 1) - gridX(i0));
        const double fy = static_cast<double>(y - gridY(j0)) / std::max(1, gridY(j0 + 1) - gridY(j0));
        consider(i0, j0, (1 - fx) * (1 - fy));
        consider(i0 + 1, j0, fx * (1 - fy));
        consider(i0, j0 + 1, (1 - fx) * fy);
        consider(i0 + 1, j0 + 1, fx * fy);
        if (!(weights > 1e-6))
          for (int j = j0 - 1; j <= j0 + 2; ++j)
            for (int i = i0 - 1; i <= i0 + 2; ++i) {
              const double dx = gridX(std::clamp(i, 0, gw - 1)) - x, dy = gridY(std::clamp(j, 0, gh - 1)) - y;
              consider(i, j, 1 / (1 + dx * dx + dy * dy));
            }
        indirect = weights > 0 ? Rgb(sum / weights)
                               : gatherAt(p, ownIndex + pixel, std::max(16, options.gatherRays / 4));
      }
      const Rgb rho = tracing_.mesh().reflectance.row(p.element).transpose().array();
      image.pixels[pixel] =
          tracing_.mesh().emission.row(p.element).transpose().array() + rho * (direct + indirect);
    }
  });
  return image;
}

}  // namespace rt
