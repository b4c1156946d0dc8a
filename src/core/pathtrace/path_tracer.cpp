#include "core/pathtrace/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/parallel.h"

namespace rt {

PathTracer::PathTracer(const Scene& scene) : tracing_(scene) {}

Rgb PathTracer::irradiance(const Vec3& origin, const Vec3& normal, int element, PairRandom& random,
                           const Vec2& light, const Vec2& bounce, int rouletteDepth, int maxBounces,
                           std::uint64_t& rays, Rgb* parts) const {
  const Mesh& mesh = tracing_.mesh();
  const RayScene& scene = tracing_.rays();
  Rgb H = Rgb::Zero();
  Rgb throughput = Rgb::Ones();
  Vec3 x = origin, n = normal;
  int at = element;
  if (parts) parts[0] = parts[1] = Rgb::Zero();
  for (int depth = 0;; ++depth) {
    // What this step adds took `depth` bounces: light reaching the path's depth-th surface.
    const Rgb before = H;
    // Next-event estimation: a point on an emitter, E cos cos / (pi r^2) V / density. Near an emitter's edge
    // (a lit wall meeting the ceiling) its variance is unbounded, so it is weighed against the bounce's own
    // chance of finding that point (power heuristic); the bounce below adds the other share.
    const Vec2 lightUv = depth == 0 ? light : Vec2(random.uniform(), random.uniform());
    const LightSample s = tracing_.sampleLight(random.uniform(), lightUv.x(), lightUv.y());
    if (s.weight > 0 && s.element != at) {
      const Vec3 d = s.point - x;
      const double r2 = d.squaredNorm();
      const double r = std::sqrt(r2);
      const double cosX = n.dot(d) / r, cosY = -s.normal.dot(d) / r;
      if (cosX > 0 && cosY > 0) {
        ++rays;
        if (scene.visible(x, s.point, at, s.element)) {
          const double lightPdf = r2 / (cosY * s.weight);  // per solid angle
          const double bouncePdf = cosX / std::numbers::pi;
          const double mis = lightPdf * lightPdf / (lightPdf * lightPdf + bouncePdf * bouncePdf);
          H += throughput * s.emission * (mis * cosX / (std::numbers::pi * lightPdf));
        }
      }
    }
    // The bounce: a cosine-distributed direction, whose pdf cancels the cosine and the 1/pi of B/pi, so the
    // radiosity leaving the hit point is the estimate of what arrives from it: its emission (weighed against
    // next-event estimation) now, and rho H there by continuing the path.
    const Vec2 uv = depth == 0 ? bounce : Vec2(random.uniform(), random.uniform());
    const Vec3 direction = cosineDirection(n, uv.x(), uv.y());
    ++rays;
    const RayHit hit = scene.firstHit(x, direction, at);
    if (hit.element < 0 || !hit.frontSide) {
      if (parts && depth < 2) parts[depth] = H - before;
      break;
    }
    const auto row = static_cast<Eigen::Index>(hit.element);
    const double density = tracing_.lightDensity(hit.element);
    if (density > 0) {
      const double cosY = -mesh.elements[static_cast<std::size_t>(hit.element)].normal.dot(direction);
      const double lightPdf = density * hit.distance * hit.distance / cosY;
      const double bouncePdf = n.dot(direction) / std::numbers::pi;
      const double mis = bouncePdf * bouncePdf / (lightPdf * lightPdf + bouncePdf * bouncePdf);
      H += throughput * mesh.emission.row(row).transpose().array() * mis;
    }
    if (parts && depth < 2) parts[depth] = H - before;
    if (maxBounces >= 0 && depth >= maxBounces) break;
    throughput *= mesh.reflectance.row(row).transpose().array();
    if (depth + 1 >= rouletteDepth) {
      // Continue with the probability of the largest channel's throughput, and divide by it: unbiased, and
      // paths in a dark or coloured room end early.
      const double survive = std::min(1.0, throughput.maxCoeff());
      if (survive <= 0 || random.uniform() >= survive) break;
      throughput /= survive;
    }
    x += hit.distance * direction;
    n = mesh.elements[static_cast<std::size_t>(hit.element)].normal;
    at = hit.element;
  }
  return H;
}

std::vector<PointEstimate> PathTracer::estimate(const std::vector<SurfacePoint>& points,
                                                const PathTraceOptions& options) const {
  std::vector<PointEstimate> out(points.size());
  const int batches = std::clamp(options.batches, 1, std::max(1, options.samples));
  const int perBatch = std::max(1, options.samples / batches);
  const StrataGrid grid(perBatch);
  parallelForChunks(0, points.size(), {}, [&](std::size_t lo, std::size_t hi) {
    std::uint64_t rays = 0;
    std::vector<int> order;
    for (std::size_t p = lo; p != hi; ++p) {
      const SurfacePoint& point = points[p];
      const int element = tracing_.locate(point);
      const Vec3 normal = point.normal.normalized();
      // A point on no known surface starts a hair above its plane, so that its own surface cannot catch its
      // rays.
      const Vec3 origin =
          element >= 0 ? point.position : Vec3(point.position + 1e-6 * tracing_.rays().sceneSize() * normal);
      RgbMean mean, direct, bounce;
      for (int b = 0; b < batches; ++b) {
        PairRandom random(options.seed, p, static_cast<std::uint64_t>(b));
        // The light samples' strata are shuffled against the bounce directions' so they do not line up.
        shuffledStrata(perBatch, random, order);
        Rgb sum = Rgb::Zero(), parts[2], partSums[2] = {Rgb::Zero(), Rgb::Zero()};
        for (int k = 0; k < perBatch; ++k) {
          sum += irradiance(origin, normal, element, random,
                            grid.sample(order[static_cast<std::size_t>(k)], random), grid.sample(k, random),
                            options.rouletteDepth, options.maxBounces, rays, parts);
          partSums[0] += parts[0];
          partSums[1] += parts[1];
        }
        mean.add(sum / perBatch);
        direct.add(partSums[0] / perBatch);
        bounce.add(partSums[1] / perBatch);
      }
      PointEstimate& e = out[p];
      e.H = mean.mean();
      e.HError = mean.standardError();
      e.HDirect = direct.mean();
      e.HDirectError = direct.standardError();
      e.HBounce = bounce.mean();
      e.HBounceError = bounce.standardError();
      e.element = element;
      if (element >= 0) {
        const Rgb rho = tracing_.mesh().reflectance.row(element).transpose().array();
        e.B = tracing_.mesh().emission.row(element).transpose().array() + rho * e.H;
        e.BError = rho * e.HError;
      }
    }
    rays_ += rays;
  });
  return out;
}

Vec3 cameraRay(const Camera& camera, int width, int height, double x, double y) {
  const Vec3 forward = (camera.target - camera.position).normalized();
  const Vec3 right = forward.cross(camera.up).normalized();
  const Vec3 up = right.cross(forward);
  const double halfHeight = std::tan(camera.fovYDegrees * std::numbers::pi / 360.0);
  const double aspect = static_cast<double>(width) / height;
  const double sx = (2 * x / width - 1) * halfHeight * aspect, sy = (1 - 2 * y / height) * halfHeight;
  return (forward + sx * right + sy * up).normalized();
}

TracedImage PathTracer::render(const Camera& camera, int width, int height,
                               const PathTraceOptions& options) const {
  TracedImage image{RgbImage(width, height), RgbImage(width, height), 0};
  const int samples = std::max(1, options.samples);
  const StrataGrid grid(samples);
  const Mesh& mesh = tracing_.mesh();
  std::atomic<std::uint64_t> total{0};
  parallelForChunks(0, static_cast<std::size_t>(height), {}, [&](std::size_t lo, std::size_t hi) {
    std::uint64_t rays = 0;
    std::vector<int> lightOrder, bounceOrder;
    for (int y = static_cast<int>(lo); y != static_cast<int>(hi); ++y)
      for (int x = 0; x < width; ++x) {
        PairRandom random(options.seed, static_cast<std::uint64_t>(y) * width + x, 0x9e3779b9u);
        shuffledStrata(samples, random, lightOrder);
        shuffledStrata(samples, random, bounceOrder);
        RgbMean mean;
        for (int k = 0; k < samples; ++k) {
          const Vec2 jitter = grid.sample(k, random);
          const Vec3 direction = cameraRay(camera, width, height, x + jitter.x(), y + jitter.y());
          ++rays;
          const RayHit hit = tracing_.rays().firstHit(camera.position, direction, -1);
          Rgb B = Rgb::Zero();
          if (hit.element >= 0 && hit.frontSide) {
            const Vec3 at = camera.position + hit.distance * direction;
            const auto row = static_cast<Eigen::Index>(hit.element);
            const Rgb H =
                irradiance(at, mesh.elements[static_cast<std::size_t>(hit.element)].normal, hit.element,
                           random, grid.sample(lightOrder[static_cast<std::size_t>(k)], random),
                           grid.sample(bounceOrder[static_cast<std::size_t>(k)], random),
                           options.rouletteDepth, options.maxBounces, rays);
            B = mesh.emission.row(row).transpose().array() +
                mesh.reflectance.row(row).transpose().array() * H;
          }
          mean.add(B);
        }
        image.B.at(x, y) = mean.mean();
        image.error.at(x, y) = mean.standardError();
      }
    total += rays;
  });
  image.rays = total;
  rays_ += total;
  return image;
}

}  // namespace rt
