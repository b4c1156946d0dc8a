#include "core/raytrace/whitted.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/formfactor/sampling.h"
#include "core/parallel.h"
#include "core/pathtrace/path_tracer.h"

namespace rt {

WhittedStats& WhittedStats::operator+=(const WhittedStats& o) {
  rays += o.rays;
  lit += o.lit;
  blocked += o.blocked;
  acne += o.acne;
  leaks += o.leaks;
  return *this;
}

struct WhittedTracer::Walk {
  PairRandom random;
  WhittedStats stats;
  RayTree* tree = nullptr;
  double time =
      0.5;  // in the shutter interval [0, 1); the moving surfaces stand where the scene has them at 1/2
};

Vec3 phongLobeDirection(const Vec3& axis, double q, double u, double v) {
  const double cosAlpha = std::pow(1.0 - u, 1.0 / (q + 1.0));  // 1 - u in (0, 1]: no zero to a power
  const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - cosAlpha * cosAlpha));
  const double phi = 2 * std::numbers::pi * v;
  // Any frame about the axis: the azimuth is uniform.
  const Vec3 helper = std::abs(axis.x()) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 t = axis.cross(helper).normalized(), b = axis.cross(t);
  return (cosAlpha * axis + sinAlpha * (std::cos(phi) * t + std::sin(phi) * b)).normalized();
}

WhittedTracer::WhittedTracer(const TracingScene& tracing, const WhittedOptions& options)
    : tracing_(tracing), options_(options) {
  options_.depth = std::max(options_.depth, 0);
  options_.shadowRays = std::max(options_.shadowRays, 1);
  options_.pixelSamples = std::max(options_.pixelSamples, 1);
  if (!(options_.lightScale > 0)) options_.lightScale = 1;
  const double s = options_.lightScale;
  for (const Emitter& e : tracing_.emitters()) {
    Light light;
    light.element = e.element;
    light.centre = Vec3::Zero();
    for (const Vec3& v : e.polygon) light.centre += v / static_cast<double>(e.polygon.size());
    for (const Vec3& v : e.polygon) light.polygon.push_back(light.centre + s * (v - light.centre));
    light.normal = e.normal;
    light.area = e.area * s * s;
    light.emission = e.emission / (s * s);
    lights_.push_back(light);
  }
  const Mesh& mesh = tracing_.mesh();
  mirror_.assign(mesh.size(), 0);
  moving_.assign(mesh.size(), 0);
  const auto listed = [](const std::vector<int>& list, int surface) {
    return std::find(list.begin(), list.end(), surface) != list.end();
  };
  for (std::size_t k = 0; k < mesh.size(); ++k) {
    const int surface = tracing_.scene().patches[static_cast<std::size_t>(mesh.elements[k].patch)].surface;
    mirror_[k] = listed(options_.mirrorSurfaces, surface);
    moving_[k] = listed(options_.movingSurfaces, surface);
  }
}

// The first hit beyond `tnear` on the moving surfaces only (`moving`) or on the standing ones only: hits on
// the others are stepped over, by a millionth of the scene, until one of the wanted kind or none is left.
RayHit WhittedTracer::firstHitAmong(const Vec3& origin, const Vec3& direction, double tnear,
                                    bool moving) const {
  const RayScene& rays = tracing_.rays();
  const double step = 1e-6 * rays.sceneSize();
  RayHit hit = rays.firstHitAfter(origin, direction, tnear);
  for (int k = 0;
       k < 256 && hit.element >= 0 && (moving_[static_cast<std::size_t>(hit.element)] != 0) != moving; ++k)
    hit = rays.firstHitAfter(origin, direction, hit.distance + step);
  return hit;
}

RayHit WhittedTracer::firstHit(const Vec3& origin, const Vec3& direction, double tnear,
                               const Walk& walk) const {
  if (!moves()) return tracing_.rays().firstHitAfter(origin, direction, tnear);
  // A surface displaced by s is hit by the ray from o where the surface at rest is hit by the ray from o - s,
  // at the same distance.
  const Vec3 shift = (walk.time - 0.5) * options_.motion;
  const RayHit standing = firstHitAmong(origin, direction, tnear, false);
  const RayHit moving = firstHitAmong(origin - shift, direction, tnear, true);
  if (moving.element < 0) return standing;
  return standing.element < 0 || moving.distance < standing.distance ? moving : standing;
}

bool WhittedTracer::clearAt(const Vec3& x, const Vec3& y, int light, const Walk& walk) const {
  if (!moves()) return tracing_.rays().visibleAfter(x, y, options_.epsilon, light);
  const Vec3 d = y - x;
  const double r = d.norm();
  if (!(r > 0)) return true;
  const RayHit hit = firstHit(x, d / r, options_.epsilon, walk);
  // The light's own plane (and a surface flush with it) is reached at r up to rounding.
  return hit.element < 0 || hit.element == light || hit.distance >= r * (1 - 1e-4);
}

// Direct light: for each light, the mean over its shadow rays of E cos cos A / (pi r^2) V, the point-to-area
// form factor's integrand sampled on the light (at its centre only for one ray: a point light). Every
// shadow ray is cast, as the cost formula counts them; a light behind the surface contributes nothing.
Rgb WhittedTracer::direct(const Vec3& x, int element, int parent, Walk& walk) const {
  const RayScene& rays = tracing_.rays();
  const Vec3& n = tracing_.mesh().elements[static_cast<std::size_t>(element)].normal;
  const int count = options_.shadowRays;
  const StrataGrid grid(count);
  Rgb H = Rgb::Zero();
  for (const Light& light : lights_) {
    for (int k = 0; k < count; ++k) {
      Vec3 y = light.centre;
      if (count > 1) {
        const Vec2 uv = grid.sample(k, walk.random);
        y = pointOnPolygon(light.polygon, uv.x(), uv.y());
      }
      ++walk.stats.rays.shadow;
      const bool clear = clearAt(x, y, light.element, walk);
      const Vec3 d = y - x;
      const double r2 = d.squaredNorm(), r = std::sqrt(r2);
      const double cosX = r > 0 ? n.dot(d) / r : 0, cosY = r > 0 ? -light.normal.dot(d) / r : 0;
      const bool facing = cosX > 0 && cosY > 0;
      // The robust test knows the scene at rest only.
      if (facing && options_.checkShadows && !moves()) {
        const bool truth = rays.visible(x, y, element, light.element);
        (truth ? walk.stats.lit : walk.stats.blocked) += 1;
        if (truth && !clear) ++walk.stats.acne;
        if (!truth && clear) ++walk.stats.leaks;
      }
      if (walk.tree) {
        RayNode node{RayKind::Shadow, parent, walk.tree->nodes[static_cast<std::size_t>(parent)].depth, x, y};
        node.blocked = !clear;
        if (!clear) {
          const RayHit hit = firstHit(x, d / r, options_.epsilon, walk);
          node.element = hit.element;
          if (hit.element >= 0) node.end = x + hit.distance * d / r;
        }
        walk.tree->nodes.push_back(node);
      }
      if (clear && facing) H += light.emission * (cosX * cosY * light.area / (std::numbers::pi * r2));
    }
  }
  return H / count;
}

// Whitted's recursion: what the ray sees is the emission and the direct light reflected there, plus, at a
// mirror below the depth limit, what the mirrored ray sees times the mirror's reflectance.
Rgb WhittedTracer::radiance(const Vec3& origin, const Vec3& direction, RayKind kind, int depth, int parent,
                            Walk& walk) const {
  const RayScene& rays = tracing_.rays();
  const Mesh& mesh = tracing_.mesh();
  ++(kind == RayKind::Primary ? walk.stats.rays.primary : walk.stats.rays.reflection);
  // The eye is on no surface: only the rays that leave a surface need the epsilon.
  const RayHit hit = firstHit(origin, direction, kind == RayKind::Primary ? 0.0 : options_.epsilon, walk);
  int self = -1;
  if (walk.tree) {
    RayNode node{kind, parent, depth, origin, origin + 0.3 * rays.sceneSize() * direction, hit.element};
    if (hit.element >= 0) node.end = origin + hit.distance * direction;
    self = static_cast<int>(walk.tree->nodes.size());
    walk.tree->nodes.push_back(node);
  }
  if (hit.element < 0 || !hit.frontSide) return Rgb::Zero();
  const auto row = static_cast<Eigen::Index>(hit.element);
  const Vec3 x = origin + hit.distance * direction;
  const Rgb rho = mesh.reflectance.row(row).transpose().array();
  Rgb B = mesh.emission.row(row).transpose().array();
  const Rgb H = direct(x, hit.element, self, walk);
  const bool mirror = mirror_[static_cast<std::size_t>(hit.element)] != 0;
  if (!mirror) B += rho * H;
  if (mirror && depth < options_.depth) {
    const Vec3& n = mesh.elements[static_cast<std::size_t>(hit.element)].normal;
    Vec3 reflected = direction - 2 * direction.dot(n) * n;
    if (options_.glossExponent > 0) {
      const double u = walk.random.uniform(), v = walk.random.uniform();
      reflected = phongLobeDirection(reflected, options_.glossExponent, u, v);
    }
    // A lobe direction below the surface reflects nothing: that part of the lobe is absorbed.
    if (reflected.dot(n) > 0) B += rho * radiance(x, reflected, RayKind::Reflection, depth + 1, self, walk);
  }
  return B;
}

Rgb WhittedTracer::directIrradiance(const Vec3& point, int element, WhittedStats& stats) const {
  Walk walk{PairRandom(options_.seed, static_cast<std::uint64_t>(element), 0x5bd1e995u), {}, nullptr};
  const Rgb H = direct(point, element, -1, walk);
  stats += walk.stats;
  return H;
}

WhittedImage WhittedTracer::render(const Camera& camera, int width, int height) const {
  WhittedImage image{
      RgbImage(width, height), std::vector<int>(static_cast<std::size_t>(width) * height, -1), {}};
  const int samples = options_.pixelSamples;
  const StrataGrid grid(samples);
  std::vector<WhittedStats> perRow(static_cast<std::size_t>(std::max(height, 0)));
  parallelForChunks(0, static_cast<std::size_t>(height), {}, [&](std::size_t lo, std::size_t hi) {
    for (int y = static_cast<int>(lo); y != static_cast<int>(hi); ++y) {
      WhittedStats& stats = perRow[static_cast<std::size_t>(y)];
      for (int x = 0; x < width; ++x) {
        const auto pixel = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(width) + x;
        Walk walk{PairRandom(options_.seed, pixel, 0x2545f491u), {}, nullptr};
        // The lens draws from a stream of its own, so that a lens and a pinhole picture share every other
        // random number: where the lens is in focus the two agree but for rounding.
        PairRandom lensRandom(options_.seed, pixel, 0x9e3779b9u);
        // The shutter's times too, so that a moving and a still picture differ only where things move.
        PairRandom timeRandom(options_.seed, pixel, 0x85ebca6bu);
        Rgb sum = Rgb::Zero();
        for (int k = 0; k < samples; ++k) {
          if (moves()) walk.time = timeRandom.uniform();
          const Vec2 jitter = samples == 1 ? Vec2(0.5, 0.5) : grid.sample(k, walk.random);
          const Vec3 d = cameraRay(camera, width, height, x + jitter.x(), y + jitter.y());
          if (options_.lens.radius > 0) {
            const double u = lensRandom.uniform(), v = lensRandom.uniform();
            const LensRay ray = thinLensRay(camera, options_.lens, d, u, v);
            sum += radiance(ray.origin, ray.direction, RayKind::Primary, 0, -1, walk);
          } else {
            sum += radiance(camera.position, d, RayKind::Primary, 0, -1, walk);
          }
        }
        image.B.at(x, y) = sum / samples;
        const RayHit centre = tracing_.rays().firstHitAfter(
            camera.position, cameraRay(camera, width, height, x + 0.5, y + 0.5), 0);
        image.element[pixel] = centre.frontSide ? centre.element : -1;
        stats += walk.stats;
      }
    }
  });
  for (const WhittedStats& s : perRow) image.stats += s;
  return image;
}

RayTree WhittedTracer::trace(const Camera& camera, int width, int height, int x, int y) const {
  RayTree tree;
  const auto pixel = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(std::max(width, 0)) + x;
  Walk walk{PairRandom(options_.seed, pixel, 0x2545f491u), {}, &tree};
  radiance(camera.position, cameraRay(camera, width, height, x + 0.5, y + 0.5), RayKind::Primary, 0, -1,
           walk);
  return tree;
}

}  // namespace rt
