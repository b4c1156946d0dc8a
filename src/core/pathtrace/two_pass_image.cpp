// The two-pass picture. A pixel's H has two parts of very different character: the emitters' direct light,
// with sharp shadow edges, and the gathered rest, which varies slowly along a surface. The direct part is
// computed exactly at every pixel (no rays where nothing can block, the hidden part cut out where something
// can); the gathered part, which costs hundreds of rays per point, is gathered only at the pixels of a grid,
// every `spacing`-th of each row and column, and interpolated between grid pixels that lie on the same patch
// and near the pixel in the scene. A pixel with no such grid pixel around it (a thin sliver of a patch, an
// edge) gathers for itself. A 1024 x 1024 picture at spacing 8 then gathers at 17k points instead of 1M.
//
// "Slowly" holds only where the surfaces the gather sees are far away. Beside a block's foot or in a corner
// the gathered light changes over the distance to the surface next to it, and a bilinear fit across a grid
// cell several times wider than that distance is wrong by several per cent. So each grid cell is split in
// four, and its new corners gathered, while the cell spans more of the surface than kCellOverDistance times
// the harmonic mean distance of its corners' gather rays, the scale over which irradiance changes (Ward,
// Rubinstein and Clear 1988, irradiance caching), down to single pixels, or while it holds pixels of more
// than one patch, down to cells two pixels wide: there every pixel has a gathered neighbour, and splitting
// such cells further would cost a quarter of all the gathers for little (docs/benchmarks.md).
//
// A pixel where one surface ends and another begins would take only the surface at its centre, so silhouettes
// come out jagged and each such pixel is wrong by the whole step in brightness. Those pixels average
// options.edgeSamples jittered samples over their square instead: each sample's direct light exact at its own
// point, its gathered light that of the nearest pixel on the same patch.

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/formfactor/sampling.h"
#include "core/parallel.h"
#include "core/pathtrace/path_tracer.h"
#include "core/pathtrace/two_pass.h"

namespace rt {
namespace {

// A cell may span at most this fraction of its corners' harmonic mean distance.
constexpr double kCellOverDistance = 1.0;
// A cell holding two patches is split while it spans more pixels than this.
constexpr int kTwoPatchesSplitDownTo = 2;

// A pixel (or an edge sample) with no gathered pixel of its own patch nearby gathers for itself, with fewer
// rays: such points are few and thin, and their noise is averaged with their neighbours'.
int ownGatherRays(const TwoPassOptions& options) {
  return std::max(16, options.gatherRays / 4);
}

struct PixelHit {
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  int element = -1;      // of the tracing mesh; -1: nothing, or the back of a polygon
  double depth = 0;      // distance from the eye
  double footprint = 0;  // the width along the surface of what one pixel sees there
};

// A rectangle of pixels whose four corners are gathered (inclusive bounds).
struct Cell {
  int x0, y0, x1, y1;
};

}  // namespace

RgbImage TwoPass::render(const Camera& camera, int width, int height, const TwoPassOptions& options,
                         int gatherSpacing) const {
  const int spacing = std::max(1, gatherSpacing);
  const double pixelAngle = 2 * std::tan(0.5 * camera.fovYDegrees * M_PI / 180) / height;
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
      // Seen at a grazing angle a pixel stretches along the surface (at most fourfold here: a surface seen
      // edge-on has few pixels to refine anyway).
      p.footprint = pixelAngle * hit.distance / std::max(0.25, std::abs(direction.dot(p.normal)));
    }
  });
  auto patchAt = [&](const PixelHit& p) { return p.element < 0 ? -1 : tracing_.patchOf(p.element); };

  // The gathered light and its harmonic mean distance at the pixels gathered so far.
  std::vector<Rgb> gathered(hits.size(), Rgb::Zero());
  std::vector<double> distance(hits.size(), std::numeric_limits<double>::infinity());
  std::vector<char> done(hits.size(), 0);
  auto gatherAt = [&](std::size_t pixel, int rays) {
    const PixelHit& p = hits[pixel];
    TwoPassOptions o = options;
    o.gatherRays = rays;
    Rgb error;
    return gather({p.position, p.normal}, p.element, o, pixel, error, nullptr, nullptr, &distance[pixel]);
  };
  auto gatherAll = [&](const std::vector<std::size_t>& pixels) {
    parallelFor(std::size_t(0), pixels.size(), [&](std::size_t k) {
      const std::size_t pixel = pixels[k];
      if (hits[pixel].element >= 0) gathered[pixel] = gatherAt(pixel, options.gatherRays);
    });
    for (const std::size_t pixel : pixels) done[pixel] = 1;
  };
  auto index = [&](int x, int y) { return static_cast<std::size_t>(y) * width + x; };

  // The grid: pixel (i * spacing, j * spacing), the last row and column clamped to the image's edge.
  const int gw = (width - 1 + spacing - 1) / spacing + 1, gh = (height - 1 + spacing - 1) / spacing + 1;
  auto gridX = [&](int i) { return std::min(i * spacing, width - 1); };
  auto gridY = [&](int j) { return std::min(j * spacing, height - 1); };
  std::vector<std::size_t> pending;
  for (int j = 0; j < gh && spacing > 1; ++j)
    for (int i = 0; i < gw; ++i) pending.push_back(index(gridX(i), gridY(j)));
  gatherAll(pending);

  // Split the cells too wide for their corners' distances, level by level, gathering each level's new corners
  // at once; the cells left unsplit are the leaves the pixels interpolate in, finer ones last.
  std::vector<Cell> cells, leaves;
  for (int j = 0; j + 1 < gh && spacing > 1; ++j)
    for (int i = 0; i + 1 < gw; ++i) cells.push_back({gridX(i), gridY(j), gridX(i + 1), gridY(j + 1)});
  auto tooWide = [&](const Cell& c) {
    const int span = std::max(c.x1 - c.x0, c.y1 - c.y0);
    const std::size_t corners[] = {index(c.x0, c.y0), index(c.x1, c.y0), index(c.x0, c.y1),
                                   index(c.x1, c.y1)};
    // Two patches inside the cell (a block's foot, a corner of the room, an outline): the pixels of each
    // interpolate only their own patch's corners, perhaps a whole cell away.
    for (const std::size_t k : corners)
      if (span > kTwoPatchesSplitDownTo && patchAt(hits[k]) != patchAt(hits[corners[0]])) return true;
    for (const std::size_t k : corners)
      if (hits[k].element >= 0 && span * hits[k].footprint > kCellOverDistance * distance[k]) return true;
    return false;
  };
  while (!cells.empty()) {
    std::vector<Cell> next;
    pending.clear();
    for (const Cell& c : cells) {
      if ((c.x1 - c.x0 < 2 && c.y1 - c.y0 < 2) || !tooWide(c)) {
        leaves.push_back(c);
        continue;
      }
      const int xm = c.x1 - c.x0 < 2 ? c.x1 : (c.x0 + c.x1) / 2;
      const int ym = c.y1 - c.y0 < 2 ? c.y1 : (c.y0 + c.y1) / 2;
      for (const Cell& child : {Cell{c.x0, c.y0, xm, ym}, Cell{xm, c.y0, c.x1, ym}, Cell{c.x0, ym, xm, c.y1},
                                Cell{xm, ym, c.x1, c.y1}}) {
        if (child.x1 < child.x0 || child.y1 < child.y0 || (child.x0 == child.x1 && c.x0 != c.x1) ||
            (child.y0 == child.y1 && c.y0 != c.y1))
          continue;  // the empty half of a cell one pixel wide or tall
        next.push_back(child);
        for (const std::size_t k : {index(child.x0, child.y0), index(child.x1, child.y0),
                                    index(child.x0, child.y1), index(child.x1, child.y1)})
          if (!done[k]) {
            done[k] = 2;  // queued
            pending.push_back(k);
          }
      }
    }
    gatherAll(pending);
    cells = std::move(next);
  }
  std::vector<int> leafOf(hits.size(), -1);
  for (std::size_t l = 0; l < leaves.size(); ++l)
    for (int y = leaves[l].y0; y <= leaves[l].y1; ++y)
      for (int x = leaves[l].x0; x <= leaves[l].x1; ++x) leafOf[index(x, y)] = static_cast<int>(l);

  RgbImage image(width, height);
  std::vector<Rgb> indirectAt(hits.size(), Rgb::Zero());
  parallelFor(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t pixel = index(x, y);
      const PixelHit& p = hits[pixel];
      if (p.element < 0) continue;
      Rgb error;
      const Rgb direct = this->direct({p.position, p.normal}, p.element, options, pixel, error);
      Rgb indirect = Rgb::Zero();
      if (spacing == 1) {
        Rgb gatherError;
        indirect = gather({p.position, p.normal}, p.element, options, pixel, gatherError);
      } else if (done[pixel] == 1) {
        indirect = gathered[pixel];
      } else {
        const int patch = patchAt(p);
        // How far apart in the scene a gathered pixel `span` pixels away may lie at depth d and still be on
        // one stretch of surface: a few times what `span` pixels span there, so that a surface seen edge-on
        // or a patch seen on both sides of a block is not bridged.
        Rgb sum = Rgb::Zero();
        double weights = 0;
        auto consider = [&](int gx, int gy, double w, int span) {
          if (gx < 0 || gy < 0 || gx >= width || gy >= height) return;
          const PixelHit& g = hits[index(gx, gy)];
          if (patchAt(g) != patch || (g.position - p.position).norm() > 4 * span * pixelAngle * p.depth)
            return;
          sum += w * gathered[index(gx, gy)];
          weights += w;
        };
        // Bilinear weights over the leaf cell's corners, then, if none of them will do, inverse distance over
        // the ring of grid cells around it.
        if (leafOf[pixel] >= 0) {
          const Cell& c = leaves[static_cast<std::size_t>(leafOf[pixel])];
          const int span = std::max(c.x1 - c.x0, c.y1 - c.y0);
          const double fx = static_cast<double>(x - c.x0) / std::max(1, c.x1 - c.x0);
          const double fy = static_cast<double>(y - c.y0) / std::max(1, c.y1 - c.y0);
          consider(c.x0, c.y0, (1 - fx) * (1 - fy), span);
          consider(c.x1, c.y0, fx * (1 - fy), span);
          consider(c.x0, c.y1, (1 - fx) * fy, span);
          consider(c.x1, c.y1, fx * fy, span);
        }
        const int i0 = x / spacing, j0 = y / spacing;
        if (!(weights > 1e-6))
          for (int j = j0 - 1; j <= j0 + 2; ++j)
            for (int i = i0 - 1; i <= i0 + 2; ++i) {
              const int gx = gridX(std::clamp(i, 0, gw - 1)), gy = gridY(std::clamp(j, 0, gh - 1));
              const double dx = gx - x, dy = gy - y;
              consider(gx, gy, 1 / (1 + dx * dx + dy * dy), spacing);
            }
        indirect = weights > 0 ? Rgb(sum / weights) : gatherAt(pixel, ownGatherRays(options));
      }
      indirectAt[pixel] = indirect;
      const Rgb rho = tracing_.mesh().reflectance.row(p.element).transpose().array();
      image.pixels[pixel] =
          tracing_.mesh().emission.row(p.element).transpose().array() + rho * (direct + indirect);
    }
  });
  std::vector<int> patchOfPixel(hits.size());
  for (std::size_t k = 0; k < hits.size(); ++k) patchOfPixel[k] = patchAt(hits[k]);
  antialiasEdges(camera, width, height, options, patchOfPixel, indirectAt, image);
  return image;
}

void TwoPass::antialiasEdges(const Camera& camera, int width, int height, const TwoPassOptions& options,
                             const std::vector<int>& patch, const std::vector<Rgb>& indirectAt,
                             RgbImage& image) const {
  const int samples = options.edgeSamples;
  if (samples <= 1) return;
  const std::size_t pixels = patch.size();
  auto patchAt = [&](int x, int y) {
    return x < 0 || y < 0 || x >= width || y >= height ? -2 : patch[static_cast<std::size_t>(y) * width + x];
  };
  std::vector<std::size_t> edges;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      bool edge = false;
      for (int dy = -1; dy <= 1 && !edge; ++dy)
        for (int dx = -1; dx <= 1 && !edge; ++dx) {
          const int other = patchAt(x + dx, y + dy);
          edge = other != -2 && other != patchAt(x, y);
        }
      if (edge) edges.push_back(static_cast<std::size_t>(y) * width + x);
    }

  const StrataGrid grid(samples);
  std::vector<Rgb> result(edges.size(), Rgb::Zero());
  parallelFor(std::size_t(0), edges.size(), [&](std::size_t e) {
    const int x = static_cast<int>(edges[e] % static_cast<std::size_t>(width));
    const int y = static_cast<int>(edges[e] / static_cast<std::size_t>(width));
    PairRandom random(options.seed, edges[e], 0x65646765);
    Rgb sum = Rgb::Zero();
    for (int k = 0; k < samples; ++k) {
      const Vec2 jitter = grid.sample(k, random);
      const Vec3 direction = cameraRay(camera, width, height, x + jitter.x(), y + jitter.y());
      const RayHit hit = tracing_.rays().firstHit(camera.position, direction, -1);
      if (hit.element < 0 || !hit.frontSide) continue;
      const SurfacePoint point{camera.position + hit.distance * direction,
                               tracing_.mesh().elements[static_cast<std::size_t>(hit.element)].normal};
      const int own = tracing_.patchOf(hit.element);
      // The gathered light of the nearest pixel whose centre lies on the sample's patch.
      Rgb indirect = Rgb::Zero();
      int best = std::numeric_limits<int>::max();
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (patchAt(x + dx, y + dy) == own && dx * dx + dy * dy < best) {
            best = dx * dx + dy * dy;
            indirect = indirectAt[static_cast<std::size_t>(y + dy) * width + x + dx];
          }
      Rgb error;
      // Streams past every pixel's own, one per sample.
      const std::uint64_t stream = pixels + edges[e] * static_cast<std::uint64_t>(samples) + k;
      if (best == std::numeric_limits<int>::max()) {
        TwoPassOptions o = options;
        o.gatherRays = ownGatherRays(options);
        indirect = gather(point, hit.element, o, stream, error);
      }
      const Rgb direct = this->direct(point, hit.element, options, stream, error);
      const Rgb rho = tracing_.mesh().reflectance.row(hit.element).transpose().array();
      sum += tracing_.mesh().emission.row(hit.element).transpose().array() + rho * (direct + indirect);
    }
    result[e] = sum / samples;
  });
  for (std::size_t e = 0; e < edges.size(); ++e) image.pixels[edges[e]] = result[e];
}

}  // namespace rt
