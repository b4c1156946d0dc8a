// The path tracer: the radiosity equation B = E + rho H solved by Monte Carlo on the scene's own polygons,
// with no mesh. It is the independent reference for global illumination: the radiosity solution is measured
// against it. Diffuse, one-sided surfaces (a ray reaching a polygon's back sees black); cosine-weighted
// bounces, next-event estimation on the emitters combined with the bounces that reach them by multiple
// importance sampling (power heuristic), Russian roulette on the path's throughput; deterministic for a seed
// whatever the number of threads.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "core/io/rgb_image.h"
#include "core/pathtrace/estimate.h"
#include "core/pathtrace/tracing_scene.h"

namespace rt {

struct PathTraceOptions {
  int samples = 4096;      // paths per point or per pixel
  int batches = 32;        // independent batches of a point's paths (standard error from their spread)
  std::uint64_t seed = 1;  //
  int rouletteDepth = 3;   // bounces before Russian roulette may end a path
  // Diffuse bounces between the first surface and the light that a path may take (-1: no limit). 0 is
  // direct light only, what a Whitted ray tracer computes for a diffuse surface; each one more adds one
  // more bounce of interreflection.
  int maxBounces = -1;
};

// What a camera sees: per pixel the radiosity B leaving the first surface hit (0 for the back of a polygon or
// nothing), and the standard error of each pixel.
struct TracedImage {
  RgbImage B;
  RgbImage error;
  std::uint64_t rays = 0;
};

class PathTracer {
 public:
  explicit PathTracer(const Scene& scene);

  // H and B at each point (TBB parallel). A point that lies on no surface gets H only (B 0, element -1).
  std::vector<PointEstimate> estimate(const std::vector<SurfacePoint>& points,
                                      const PathTraceOptions& options) const;

  TracedImage render(const Camera& camera, int width, int height, const PathTraceOptions& options) const;

  const TracingScene& tracing() const { return tracing_; }
  // Rays cast so far (shadow rays included), for rates.
  std::uint64_t raysCast() const { return rays_; }

 private:
  // One path's estimate of H at `origin` (on element `element`, -1 for none), its first light sample and
  // bounce direction drawn from the strata `light` and `bounce`. `parts` (when given) receives the share of
  // H that took no bounce and one bounce.
  Rgb irradiance(const Vec3& origin, const Vec3& normal, int element, PairRandom& random, const Vec2& light,
                 const Vec2& bounce, int rouletteDepth, int maxBounces, std::uint64_t& rays,
                 Rgb* parts = nullptr) const;

  TracingScene tracing_;
  mutable std::atomic<std::uint64_t> rays_{0};
};

// The ray through pixel (x, y) (real coordinates: x + 0.5 is the centre of column x; y grows downwards) of a
// width x height image seen by `camera`: unit direction from the camera's position.
Vec3 cameraRay(const Camera& camera, int width, int height, double x, double y);

}  // namespace rt
