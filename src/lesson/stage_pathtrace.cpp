// The pathtrace stage: one equation, two solutions. The radiosity solution on the step's mesh is pictured
// through the scene's camera beside the path tracer's image of the same scene (Monte Carlo on the polygons
// themselves, no mesh), their difference separates the mesh's artefacts from the tracer's noise, the noise
// is measured at a few numbers of paths per pixel, and the two-pass image reads the same solution through a
// second pass at each pixel. Every image is `image-size` square; every number is relative to the mean of the
// path-traced image, as `radiosity compare-pt` reports them.
#include <chrono>
#include <cmath>
#include <memory>

#include "core/assembly.h"
#include "core/pathtrace/image_compare.h"
#include "core/pathtrace/two_pass.h"
#include "lesson/step_stages.h"

namespace rt::lesson {
double imageMean(const RgbImage& image) {
  double sum = 0;
  for (const Rgb& p : image.pixels) sum += p.mean();
  return image.pixels.empty() ? 0.0 : sum / static_cast<double>(image.pixels.size());
}

namespace detail {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double rmsOf(const RgbImage& image) {
  double sum = 0;
  for (const Rgb& p : image.pixels) sum += p.square().sum();
  return image.pixels.empty() ? 0.0 : std::sqrt(sum / (3.0 * static_cast<double>(image.pixels.size())));
}

void checkCancelled(const Progress& progress) {
  if (progress.cancelled()) throw Cancelled();
}

}  // namespace

void computePathTrace(StageContext& c) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  const int size = p.imageSize;
  const std::uint64_t seed = p.seed.value_or(1);

  // The radiosity solution, as the solve stage computes it.
  r.method = c.method();
  r.F = c.formFactors(r.mesh, r.method, "method", r.formFactorStats);
  addFormFactorValues(r, *r.F);
  const RadiositySystem system = RadiositySystem::fromMesh(r.mesh, *r.F);
  r.runs.push_back(runSolver(c, p.solver, system, r.B, p.solver, true));
  const double solveSeconds = r.formFactorStats.seconds + r.runs.back().seconds;
  checkCancelled(c.progress);
  const std::string key = picturesKey(c, {});
  if (auto kept = c.runner.keptPictures<TracedPictures>(key)) {
    for (const auto& [name, value] : kept->values) r.values[name] = value;
    r.pictures = std::move(kept);
    return;
  }

  auto pictures = std::make_shared<TracedPictures>();
  c.progress.report(0.3, "path tracing");
  auto start = std::chrono::steady_clock::now();
  const PathTracer tracer(r.scene);
  PathTraceOptions traceOptions;
  traceOptions.samples = p.paths;
  traceOptions.seed = seed;
  pictures->pathTraced = tracer.render(r.camera, size, size, traceOptions);
  const double traceSeconds = secondsSince(start);
  pictures->mean = imageMean(pictures->pathTraced.B);
  const double mean = pictures->mean > 0 ? pictures->mean : 1.0;
  checkCancelled(c.progress);

  // The noise at 1/64, 1/16 and 1/4 of the paths: two images with different seeds differ by sqrt 2 times
  // one image's noise, a measure that needs no reference and includes what stratification gains.
  c.progress.report(0.6, "noise");
  std::vector<double> paths, measured;
  for (int divisor : {64, 16, 4}) {
    const int n = p.paths / divisor;
    if (n < 1) continue;
    PathTraceOptions a = traceOptions;
    a.samples = n;
    a.seed = seed + 1000;
    PathTraceOptions b = a;
    b.seed = seed + 2000;
    const TracedImage first = tracer.render(r.camera, size, size, a);
    const TracedImage second = tracer.render(r.camera, size, size, b);
    NoisePoint point{n, rmsDifference(first.B, second.B) / std::sqrt(2.0) / mean, rmsOf(first.error) / mean};
    pictures->noise.push_back(point);
    paths.push_back(n);
    measured.push_back(point.measured);
    checkCancelled(c.progress);
  }
  pictures->slope = logLogSlope(paths, measured);

  // The solution's flat elements seen through the same camera, and the two-pass image.
  c.progress.report(0.8, "two-pass image");
  const RayScene rays(r.mesh);
  pictures->radiosity = renderElements(r.mesh, r.B, rays, r.camera, size, size);
  start = std::chrono::steady_clock::now();
  TwoPassOptions twoPassOptions;
  twoPassOptions.gatherRays = p.gatherRays;
  twoPassOptions.shadowRays = 64;
  twoPassOptions.batches = 8;
  twoPassOptions.seed = seed;
  const TwoPass twoPass(tracer.tracing(), r.mesh, r.B, r.F.get());
  pictures->twoPass = twoPass.render(r.camera, size, size, twoPassOptions);
  const double twoPassSeconds = secondsSince(start);

  const ImageError radiosityError = compareToReference(pictures->radiosity, pictures->pathTraced);
  const ImageError twoPassError = compareToReference(pictures->twoPass, pictures->pathTraced);
  auto& v = pictures->values;
  v["rms.radiosity"] = radiosityError.rmsDifference;
  v["rms.two-pass"] = twoPassError.rmsDifference;
  v["error.radiosity"] = radiosityError.error;
  v["error.two-pass"] = twoPassError.error;
  v["noise.path-traced"] = radiosityError.referenceNoise;
  v["noise-slope"] = pictures->slope;
  for (std::size_t k = 0; k < pictures->noise.size(); ++k) {
    v["noise[" + std::to_string(k) + "]"] = pictures->noise[k].measured;
    v["noise-paths[" + std::to_string(k) + "]"] = pictures->noise[k].paths;
  }
  v["paths"] = p.paths;
  v["gather-rays"] = p.gatherRays;
  v["pixels"] = static_cast<double>(size) * size;
  v["rays.path-traced"] = static_cast<double>(pictures->pathTraced.rays);
  v["seconds.solve"] = solveSeconds;
  v["seconds.trace"] = traceSeconds;
  v["seconds.two-pass"] = twoPassSeconds;
  v["mean.path-traced"] = pictures->mean;
  for (const auto& [name, value] : v) r.values[name] = value;
  c.runner.keepPictures<TracedPictures>(key, pictures);
  r.pictures = std::move(pictures);
}

}  // namespace detail
}  // namespace rt::lesson
