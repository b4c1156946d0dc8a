// A recursive (Whitted) ray tracer over the program's scenes: a primary ray per pixel sample, shadow rays
// from every surface it reaches to every light, and a mirror ray from every mirror up to a depth. It shares
// the path tracer's scene (core/pathtrace/tracing_scene.h: the Embree geometry, the emitters as area lights)
// and measures what the path tracer does in the same units: the radiosity B leaving the surface each pixel
// sees, here with direct light only (Whitted 1980, without the ambient term).
//
// Two of its settings are the lessons' subject. One shadow ray per light goes to the light's centre, a
// point light: hard shadows; n go to a jittered grid on the light's area: soft ones (Cook, Porter and
// Carpenter 1984). Secondary rays count hits only beyond `epsilon` along the ray, the classic remedy for a
// ray finding the surface it leaves at a rounding-error distance: 0 gives shadow acne, too large a value lets
// light through near contacts. The tracer counts its rays by kind, and can check each shadow ray against
// the robust visibility test to count the acne and the leaks. Mirrors may be glossy: each reflected ray then
// samples a Phong lobe about the mirror direction (see phongLobeDirection). The camera may have a thin lens
// (core/raytrace/thin_lens.h): depth of field. Some surfaces may move while the shutter is open: each primary
// ray then sees the scene at its own time (motion blur).
#pragma once

#include <cstdint>
#include <vector>

#include "core/io/rgb_image.h"
#include "core/pathtrace/tracing_scene.h"
#include "core/raytrace/ray_tree.h"
#include "core/raytrace/thin_lens.h"

namespace rt {

struct WhittedOptions {
  int depth = 3;          // mirror reflections followed at most
  int shadowRays = 1;     // per light per hit: 1 = to the light's centre (hard), n = over its area (soft)
  double epsilon = 0;     // secondary rays ignore hits closer than this (scene units)
  double lightScale = 1;  // each light scaled about its centre, its power kept
  int pixelSamples = 1;   // primary rays per pixel, jittered (antialiasing)
  // Mirrors' gloss: 0 reflects every ray exactly (an ideal mirror); q > 0 sends each reflected ray in a
  // direction drawn from the Phong lobe cos^q about the mirror direction (glossy reflection), so that the
  // primary rays of a pixel average the lobe (distributed ray tracing).
  double glossExponent = 0;
  // The camera's lens (depth of field): a radius above 0 sends each primary ray from its own point of the
  // aperture through the plane of focus, so that the pixel's rays average the lens.
  ThinLens lens;
  // Motion blur: the surfaces listed move by `motion` (scene units) while the shutter is open, from -motion/2
  // to +motion/2 about where the scene puts them, at a constant velocity. Each primary ray draws its own
  // time in the shutter interval and every ray of its tree sees the moving surfaces there, shadow rays
  // included (so their shadows move too). The moving surfaces must not emit: the lights stay where they are.
  std::vector<int> movingSurfaces;
  Vec3 motion = Vec3::Zero();
  std::vector<int> mirrorSurfaces;  // surfaces (indices into the scene's) that reflect as mirrors
  std::uint64_t seed = 1;
  bool checkShadows = false;  // also test each shadow ray robustly: acne and leak counts (at rest only)
};

struct WhittedStats {
  RayCounts rays;
  // Shadow rays towards a light in front of the surface, with checkShadows: `lit` of them reach it by the
  // robust test, `acne` of those the tracer thought blocked; `leaks` of the others it thought clear.
  std::uint64_t lit = 0, blocked = 0, acne = 0, leaks = 0;
  double acneFraction() const { return lit ? static_cast<double>(acne) / static_cast<double>(lit) : 0.0; }
  double leakFraction() const {
    return blocked ? static_cast<double>(leaks) / static_cast<double>(blocked) : 0.0;
  }
  WhittedStats& operator+=(const WhittedStats& o);
};

struct WhittedImage {
  RgbImage B;
  std::vector<int> element;  // per pixel, the element the centre's primary ray reaches (-1: none)
  WhittedStats stats;
};

// A direction drawn from the density (q + 1) / (2 pi) cos^q(alpha) over the sphere of directions about the
// unit vector `axis`, alpha the angle to it, from two uniform numbers in [0, 1): cos(alpha) = u^(1 / (q + 1))
// and the azimuth 2 pi v. q = 0 gives the uniform hemisphere about `axis`; large q a narrow cone.
Vec3 phongLobeDirection(const Vec3& axis, double q, double u, double v);

class WhittedTracer {
 public:
  // `tracing` must outlive the tracer.
  WhittedTracer(const TracingScene& tracing, const WhittedOptions& options);

  WhittedImage render(const Camera& camera, int width, int height) const;  // TBB parallel, deterministic
  // The ray tree of the first sample of pixel (x, y), the ray through its centre.
  RayTree trace(const Camera& camera, int width, int height, int x, int y) const;
  // The direct irradiance H the shadow rays estimate at `point` on element `element` of the tracing mesh.
  Rgb directIrradiance(const Vec3& point, int element, WhittedStats& stats) const;

  int lights() const { return static_cast<int>(lights_.size()); }

 private:
  struct Light {
    int element = -1;
    Polygon polygon;  // scaled
    Vec3 centre, normal;
    double area = 0;
    Rgb emission = Rgb::Zero();  // scaled so that emission * area stays the emitter's
  };
  struct Walk;  // one sample's random numbers, counters and (optionally) its tree

  Rgb radiance(const Vec3& origin, const Vec3& direction, RayKind kind, int depth, int parent,
               Walk& walk) const;
  Rgb direct(const Vec3& point, int element, int parent, Walk& walk) const;
  bool moves() const { return options_.motion != Vec3::Zero() && !options_.movingSurfaces.empty(); }
  // The first hit after `tnear` at the walk's time: the scene at rest without motion; with it, the nearer
  // of the first standing surface and the first moving one, the latter found by moving the ray instead.
  RayHit firstHit(const Vec3& origin, const Vec3& direction, double tnear, const Walk& walk) const;
  RayHit firstHitAmong(const Vec3& origin, const Vec3& direction, double tnear, bool moving) const;
  // Whether the shadow ray from x to the point y of light element `light` is clear, at the walk's time.
  bool clearAt(const Vec3& x, const Vec3& y, int light, const Walk& walk) const;

  const TracingScene& tracing_;
  WhittedOptions options_;
  std::vector<Light> lights_;
  std::vector<char> mirror_;  // per element of the tracing mesh
  std::vector<char> moving_;  // per element of the tracing mesh
};

}  // namespace rt
