// The raytrace stage: the step's scene rendered by recursive (Whitted) ray tracing, beside the radiosity
// solution of the same scene. The tracer (core/raytrace) counts the rays it casts by kind, and the stage
// sets them against the cost formula over a range of depths; it renders the hard and soft shadows of one
// and of `shadow-rays` shadow rays, the acne and leaks of an epsilon of 0, the step's and a too large one,
// renders the step's lens beside a pinhole (depth of field) and its moving surfaces beside the same standing
// still (motion blur), and records the ray tree of one pixel.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>

#include "core/pathtrace/image_compare.h"
#include "core/pathtrace/path_tracer.h"
#include "core/raytrace/ray_cost.h"
#include "core/raytrace/thin_lens.h"
#include "core/raytrace/whitted.h"
#include "lesson/step_stages.h"
#include "lesson/traced_pictures.h"

namespace rt::lesson::detail {
namespace {

// The surfaces named in the list `key` (`mirrors`, `moving`), as indices into the scene's surfaces.
std::vector<int> namedSurfaces(const StageContext& c, const std::string& key, const std::string& list) {
  std::vector<int> out;
  std::istringstream names(list);
  std::string name;
  while (std::getline(names, name, ',')) {
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    if (name.empty()) continue;
    const auto& surfaces = c.result.scene.surfaces;
    const auto found =
        std::find_if(surfaces.begin(), surfaces.end(), [&](const Surface& s) { return s.name == name; });
    if (found == surfaces.end()) c.fail(key, "the scene has no surface '" + name + "'");
    out.push_back(static_cast<int>(found - surfaces.begin()));
  }
  return out;
}

// The pixels whose centre sees `surface` (and, with a column range, lie in it). With `interior`, only pixels
// whose eight neighbours see the same surface count: a supersampled pixel on an edge mixes in its neighbour
// (the light's, a hundred times brighter).
std::vector<std::size_t> surfacePixels(const RgbImage& image, const std::vector<int>& elements,
                                       const Mesh& mesh, const Scene& scene, const std::string& surface,
                                       bool interior, int fromColumn = 0, int toColumn = 1 << 30) {
  const auto surfaceAt = [&](int x, int y) {
    const int e = elements[static_cast<std::size_t>(y) * image.width + x];
    if (e < 0) return -1;
    return scene.patches[static_cast<std::size_t>(mesh.elements[static_cast<std::size_t>(e)].patch)].surface;
  };
  std::vector<std::size_t> out;
  for (int y = 1; y + 1 < image.height; ++y)
    for (int x = std::max(1, fromColumn); x < std::min(image.width - 1, toColumn); ++x) {
      const int here = surfaceAt(x, y);
      if (here < 0 || scene.surfaces[static_cast<std::size_t>(here)].name != surface) continue;
      bool inside = true;
      for (int dy = -1; interior && dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) inside = inside && surfaceAt(x + dx, y + dy) == here;
      if (inside) out.push_back(static_cast<std::size_t>(y) * image.width + x);
    }
  return out;
}

// Means over those pixels, per channel.
Rgb surfaceMeanOf(const RgbImage& image, const std::vector<int>& elements, const Mesh& mesh,
                  const Scene& scene, const std::string& surface, int fromColumn = 0,
                  int toColumn = 1 << 30) {
  const auto pixels = surfacePixels(image, elements, mesh, scene, surface, true, fromColumn, toColumn);
  Rgb sum = Rgb::Zero();
  for (const std::size_t k : pixels) sum += image.pixels[k];
  return pixels.empty() ? Rgb::Zero() : Rgb(sum / static_cast<double>(pixels.size()));
}

// Per surface: the mean depth along the view of its pixels, and the RMS difference of the picture `changed`
// from `still` over its pixels (edges included: that is where a blur shows), relative to `still`'s mean, as
// `<name>-difference.<surface>`.
void addDifferenceValues(StageContext& c, const TracingScene& tracing, const std::vector<int>& elements,
                         const RgbImage& still, const RgbImage& changed, const std::string& name) {
  const StepResult& r = c.result;
  const int size = c.parameters.imageSize;
  const Vec3 forward = (r.camera.target - r.camera.position).normalized();
  std::vector<double> depth(static_cast<std::size_t>(size) * size, 0.0);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const Vec3 dir = cameraRay(r.camera, size, size, x + 0.5, y + 0.5);
      const RayHit hit = tracing.rays().firstHitAfter(r.camera.position, dir, 0);
      if (hit.element >= 0) depth[static_cast<std::size_t>(y) * size + x] = hit.distance * dir.dot(forward);
    }
  auto& v = c.result.values;
  const double mean = imageMean(still);
  for (const Surface& surface : r.scene.surfaces) {
    const auto pixels = surfacePixels(still, elements, tracing.mesh(), r.scene, surface.name, true);
    if (pixels.empty()) continue;
    double z = 0, squares = 0;
    for (const std::size_t k : pixels) {
      z += depth[k];
      squares += (changed.pixels[k] - still.pixels[k]).matrix().squaredNorm() / 3;
    }
    const double n = static_cast<double>(pixels.size());
    v["depth." + surface.name] = z / n;
    v[name + "-difference." + surface.name] = mean > 0 ? std::sqrt(squares / n) / mean : 0.0;
  }
}

// The depth of field on each surface: its depth and difference from the pinhole's picture, and the blur
// disc the lens gives a point at that depth.
void addFocusValues(StageContext& c, const TracingScene& tracing, const std::vector<int>& elements,
                    const ThinLens& lens, const RayTraceData& d) {
  addDifferenceValues(c, tracing, elements, d.pinhole, d.whitted, "focus");
  auto& v = c.result.values;
  for (const Surface& surface : c.result.scene.surfaces)
    if (v.count("depth." + surface.name))
      v["blur-disc." + surface.name] =
          blurDiscPixels(c.result.camera, lens, c.parameters.imageSize, v["depth." + surface.name]);
}

// Motion blur: each surface's difference from the still picture, and for the moving ones the distance they
// travel across the image while the shutter is open, in pixels at the image's centre: the motion across the
// view over the depth, over the angle of one pixel.
void addMotionValues(StageContext& c, const TracingScene& tracing, const std::vector<int>& elements,
                     const std::vector<int>& moving, const Vec3& motion, const RayTraceData& d) {
  addDifferenceValues(c, tracing, elements, d.still, d.whitted, "motion");
  const StepResult& r = c.result;
  auto& v = c.result.values;
  const Vec3 forward = (r.camera.target - r.camera.position).normalized();
  const double across = (motion - motion.dot(forward) * forward).norm();
  const double pixel = 2 * std::tan(r.camera.fovYDegrees * std::numbers::pi / 360) / c.parameters.imageSize;
  for (const int s : moving) {
    const std::string& name = r.scene.surfaces[static_cast<std::size_t>(s)].name;
    if (v.count("depth." + name)) v["motion-pixels." + name] = across / v["depth." + name] / pixel;
  }
}

}  // namespace

void computeRayTrace(StageContext& c) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  const int size = p.imageSize;
  if (p.pixelX >= size)
    c.fail("pixel-x", "the pixel lies outside the image (image-size " + std::to_string(size) + ")");
  if (p.pixelY >= size)
    c.fail("pixel-y", "the pixel lies outside the image (image-size " + std::to_string(size) + ")");
  const std::vector<int> mirrors = namedSurfaces(c, "mirrors", p.mirrors);
  const std::vector<int> moving = namedSurfaces(c, "moving", p.moving);
  for (const int s : moving) {
    const Surface& surface = r.scene.surfaces[static_cast<std::size_t>(s)];
    if (r.scene.materials[static_cast<std::size_t>(surface.material)].isEmitter())
      c.fail("moving", "'" + surface.name + "' emits light, and the lights stand still");
  }

  // The radiosity solution, as the solve stage computes it.
  r.method = c.method();
  r.F = c.formFactors(r.mesh, r.method, "method", r.formFactorStats);
  addFormFactorValues(r, *r.F);
  const RadiositySystem system = RadiositySystem::fromMesh(r.mesh, *r.F);
  r.runs.push_back(runSolver(c, p.solver, system, r.B, p.solver, true));
  if (c.progress.cancelled()) throw Cancelled();
  c.progress.report(0.4, "ray tracing");

  // The pictures only the step's views show are made only for them (the app runs a step at every change).
  const auto wants = [&c](View view) {
    return std::find(c.step.views.begin(), c.step.views.end(), view) != c.step.views.end();
  };
  auto data = std::make_shared<RayTraceData>();
  RayTraceData& d = *data;
  const TracingScene tracing(r.scene);
  WhittedOptions options;
  options.depth = p.rayDepth;
  options.shadowRays = p.shadowRays;
  options.epsilon = p.rayEpsilon;
  options.lightScale = p.lightSize;
  options.glossExponent = p.gloss;
  options.pixelSamples = p.pixelSamples;
  options.lens = {p.aperture, p.focusDistance};
  options.mirrorSurfaces = mirrors;
  options.movingSurfaces = moving;
  options.motion = Vec3(p.motion, 0, 0);
  options.seed = p.seed.value_or(1);
  options.checkShadows = true;
  const auto start = std::chrono::steady_clock::now();
  const WhittedTracer tracer(tracing, options);
  const WhittedImage main = tracer.render(r.camera, size, size);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  d.whitted = main.B;
  d.epsilon = p.rayEpsilon;
  d.shadowRays = p.shadowRays;
  d.depth = p.rayDepth;
  d.lights = tracer.lights();
  d.pixelX = p.pixelX;
  d.pixelY = p.pixelY;
  d.gloss = p.gloss;
  d.pixelSamples = p.pixelSamples;
  d.tree = tracer.trace(r.camera, size, size, p.pixelX, p.pixelY);
  if (wants(View::Glossy)) {
    WhittedOptions ideal = options;
    ideal.glossExponent = 0;
    d.idealMirrors = WhittedTracer(tracing, ideal).render(r.camera, size, size).B;
  }
  d.aperture = p.aperture;
  d.focusDistance = focusDistanceOf(r.camera, options.lens);
  if (wants(View::Focus)) {
    WhittedOptions pinhole = options;
    pinhole.lens.radius = 0;
    d.pinhole = WhittedTracer(tracing, pinhole).render(r.camera, size, size).B;
  }
  d.motion = p.motion;
  if (wants(View::Motion)) {
    WhittedOptions still = options;
    still.motion = Vec3::Zero();
    d.still = WhittedTracer(tracing, still).render(r.camera, size, size).B;
  }

  // One shadow ray per light: the hard shadows, and the epsilon's acne unblurred by the light's area.
  WhittedOptions single = options;
  single.shadowRays = 1;
  if (wants(View::Shadows)) d.hard = WhittedTracer(tracing, single).render(r.camera, size, size).B;
  // Too large: a fifth of the scene, the height of a block, which shadow rays near its base then skip whole.
  d.largeEpsilon = 0.2 * tracing.rays().sceneSize();
  WhittedStats zeroStats, stepStats, largeStats;
  if (wants(View::Epsilon))
    for (auto [epsilon, image, stats] :
         {std::tuple{0.0, &d.epsilonZero, &zeroStats}, std::tuple{p.rayEpsilon, &d.epsilonStep, &stepStats},
          std::tuple{d.largeEpsilon, &d.epsilonLarge, &largeStats}}) {
      single.epsilon = epsilon;
      WhittedImage traced = WhittedTracer(tracing, single).render(r.camera, size, size);
      *image = std::move(traced.B);
      *stats = traced.stats;
    }
  if (c.progress.cancelled()) throw Cancelled();

  // Rays per pixel against the depth limit, counted on a small image (the count per pixel hardly depends on
  // the image's size), against the full tree of the formula.
  c.progress.report(0.7, "counting rays");
  const int small = 32;
  RayCostInputs in;
  in.pixels = static_cast<std::int64_t>(size) * size;
  in.lights = d.lights;
  in.shadowRays = p.shadowRays;
  in.pixelSamples = p.pixelSamples;
  in.depth = p.rayDepth;
  const RayCost cost = whittedRayCost(in);
  for (int depth = 0; wants(View::RayCost) && depth <= std::max(6, p.rayDepth); ++depth) {
    WhittedOptions o = options;
    o.depth = depth;
    o.checkShadows = false;
    const WhittedImage counted = WhittedTracer(tracing, o).render(r.camera, small, small);
    RayCostInputs at = in;
    at.depth = depth;
    d.depths.push_back(depth);
    d.formula.push_back(whittedRayCost(at).perPixel);
    d.counted.push_back(static_cast<double>(counted.stats.rays.total()) / (small * small));
  }

  // The path tracer, one more bounce at a time: 0 is the direct light Whitted's diffuse surfaces show.
  c.progress.report(0.8, "path tracing");
  const PathTracer pathTracer(r.scene);
  d.paths = p.paths;
  for (const int bounces : {0, 1, 2, -1}) {
    if (!wants(View::PathBounces)) break;
    PathTraceOptions o;
    o.samples = p.paths;
    o.seed = options.seed;
    o.maxBounces = bounces;
    d.bounceLimits.push_back(bounces);
    d.pathBounces.push_back(pathTracer.render(r.camera, size, size, o).B);
    if (c.progress.cancelled()) throw Cancelled();
  }

  const RayScene rays(r.mesh);
  d.radiosity = renderElements(r.mesh, r.B, rays, r.camera, size, size);

  auto& v = r.values;
  const double pixels = static_cast<double>(size) * size;
  const RayCounts& n = main.stats.rays;
  v["pixels"] = pixels;
  v["image-size"] = size;
  v["lights"] = d.lights;
  v["shadow-rays"] = p.shadowRays;
  v["ray-depth"] = p.rayDepth;
  v["epsilon"] = p.rayEpsilon;
  v["light-size"] = p.lightSize;
  v["gloss"] = p.gloss;
  v["pixel-samples"] = p.pixelSamples;
  if (wants(View::Glossy)) {
    // How far the glossy picture is from the ideal mirrors', RMS over the pixels relative to the mean.
    const double mean = imageMean(d.whitted);
    v["gloss-difference"] = mean > 0 ? rmsDifference(d.whitted, d.idealMirrors) / mean : 0.0;
  }
  v["aperture"] = p.aperture;
  v["focus-distance"] = d.focusDistance;
  if (wants(View::Focus)) addFocusValues(c, tracing, main.element, options.lens, d);
  v["motion"] = p.motion;
  if (wants(View::Motion)) addMotionValues(c, tracing, main.element, moving, options.motion, d);
  v["rays.primary"] = static_cast<double>(n.primary);
  v["rays.shadow"] = static_cast<double>(n.shadow);
  v["rays.reflection"] = static_cast<double>(n.reflection);
  v["rays.total"] = static_cast<double>(n.total());
  v["rays-per-pixel"] = static_cast<double>(n.total()) / pixels;
  v["rays-per-pixel.formula"] = cost.perPixel;
  v["rays.formula"] = cost.total;
  v["tree-nodes.formula"] = cost.treeNodes;
  v["seconds.whitted"] = seconds;
  v["rays-per-second"] = seconds > 0 ? static_cast<double>(n.total()) / seconds : 0.0;
  v["million-rays-per-second"] = v["rays-per-second"] / 1e6;
  v["acne"] = main.stats.acneFraction();
  v["leaks"] = main.stats.leakFraction();
  if (wants(View::Epsilon)) {
    v["acne.zero"] = zeroStats.acneFraction();
    v["acne.step"] = stepStats.acneFraction();
    v["leaks.step"] = stepStats.leakFraction();
    v["acne.large"] = largeStats.acneFraction();
    v["leaks.large"] = largeStats.leakFraction();
    v["epsilon.large"] = d.largeEpsilon;
  }
  v["scene-size"] = tracing.rays().sceneSize();
  const RayCounts t = d.tree.counts();
  v["tree.rays"] = static_cast<double>(t.total());
  v["tree.shadow"] = static_cast<double>(t.shadow);
  v["tree.reflection"] = static_cast<double>(t.reflection);
  int blocked = 0;
  for (const RayNode& node : d.tree.nodes) blocked += node.kind == RayKind::Shadow && node.blocked;
  v["tree.blocked"] = blocked;
  v["pixel-x"] = p.pixelX;
  v["pixel-y"] = p.pixelY;
  v["mean.whitted"] = imageMean(d.whitted);
  v["mean.radiosity"] = imageMean(d.radiosity);
  // Diffuse interreflection, which Whitted's rays never follow: the ceiling, which the light (in its plane)
  // does not reach directly, and the colour the red wall lends the white back wall's left third against
  // its right third (the green wall's side): a ratio of red over green ratios, 1 without colour bleeding.
  const Mesh& traced = tracing.mesh();
  const RgbImage& whittedB = d.whitted;
  v["ceiling.whitted"] = surfaceMeanOf(whittedB, main.element, traced, r.scene, "ceiling").mean();
  v["ceiling.radiosity"] = surfaceMeanOf(d.radiosity, main.element, traced, r.scene, "ceiling").mean();
  v["floor.whitted"] = surfaceMeanOf(whittedB, main.element, traced, r.scene, "floor").mean();
  auto bleed = [&](const RgbImage& image) {
    const Rgb left = surfaceMeanOf(image, main.element, traced, r.scene, "back_wall", 0, size / 3);
    const Rgb right = surfaceMeanOf(image, main.element, traced, r.scene, "back_wall", size - size / 3);
    return left(1) > 0 && right(1) > 0 && right(0) > 0 ? (left(0) / left(1)) / (right(0) / right(1)) : 0.0;
  };
  v["bleed.whitted"] = bleed(d.whitted);
  v["bleed.radiosity"] = bleed(d.radiosity);
  v["paths"] = p.paths;
  const char* names[] = {"0", "1", "2", "all"};
  for (std::size_t k = 0; k < d.pathBounces.size(); ++k) {
    v[std::string("mean.path.") + names[k]] = imageMean(d.pathBounces[k]);
    v[std::string("ceiling.path.") + names[k]] =
        surfaceMeanOf(d.pathBounces[k], main.element, traced, r.scene, "ceiling").mean();
    v[std::string("bleed.path.") + names[k]] = bleed(d.pathBounces[k]);
    v[std::string("floor.path.") + names[k]] =
        surfaceMeanOf(d.pathBounces[k], main.element, traced, r.scene, "floor").mean();
  }
  r.raytrace = std::move(data);
}

}  // namespace rt::lesson::detail
