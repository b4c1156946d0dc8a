// radiosity compare-pt: the radiosity solution against the path tracer, the independent Monte Carlo solution
// of the same equation with no mesh. Renders both (and the two-pass picture) from the scene's camera, prints
// each one's RMS error against the path-traced image with the path tracer's noise taken out and a 95 %
// interval, and writes the images and the error images.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/solution.h"
#include "core/io/scene_loader.h"
#include "core/pathtrace/image_compare.h"
#include "core/pathtrace/two_pass.h"

namespace rt::cli {
namespace {

struct CompareArguments {
  std::string scene;
  CameraArgument camera;
  std::string output = "compare-pt";
  SolutionArguments solution;
  int width = 160, height = 160;
  int paths = 1024;       // per pixel
  int gatherRays = 256;   // per gathered pixel of the two-pass picture
  int gatherSpacing = 1;  // gather at every this many pixels of a row and column, interpolate between
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void writeImages(const std::string& folder, const std::string& name, const RgbImage& image, double scale) {
  writePfm(image, folder + "/" + name + ".pfm");
  writePpm(image, scale, folder + "/" + name + ".ppm");
}

void run(const CompareArguments& a) {
  std::filesystem::create_directories(a.output);
  Scene scene = loadSceneReportingWarnings(a.scene);
  a.camera.applyTo(scene);
  requireLight(scene);
  const Camera camera = scene.cameraOrDefault();
  auto start = std::chrono::steady_clock::now();
  Pipeline pipeline;
  const Solution solution = solveOnMesh(scene, a.solution, pipeline);
  const double solveSeconds = secondsSince(start);

  start = std::chrono::steady_clock::now();
  const PathTracer tracer(scene);
  PathTraceOptions traceOptions;
  traceOptions.samples = a.paths;
  traceOptions.seed = a.solution.seed;
  const TracedImage reference = tracer.render(camera, a.width, a.height, traceOptions);
  const double traceSeconds = secondsSince(start);

  const RayScene rays(solution.mesh);
  const RgbImage radiosity =
      renderElements(solution.mesh, solution.outcome.B, rays, camera, a.width, a.height);
  start = std::chrono::steady_clock::now();
  TwoPassOptions twoPassOptions;
  twoPassOptions.gatherRays = a.gatherRays;
  twoPassOptions.shadowRays = 64;
  twoPassOptions.batches = 8;
  twoPassOptions.seed = a.solution.seed;
  const TwoPass twoPass(tracer.tracing(), solution.mesh, solution.outcome.B,
                        solution.formFactors ? &solution.formFactors->F : nullptr);
  const RgbImage twoPassImage = twoPass.render(camera, a.width, a.height, twoPassOptions, a.gatherSpacing);
  const double twoPassSeconds = secondsSince(start);

  // One exposure for every picture: the path-traced image's mean maps to 18 % grey.
  const double scale = middleGreyScale(reference.B);
  const double mean = 0.18 / scale;
  writeImages(a.output, "path-traced", reference.B, scale);
  writePfm(reference.error, a.output + "/path-traced-error.pfm");
  writeImages(a.output, "radiosity", radiosity, scale);
  writeImages(a.output, "two-pass", twoPassImage, scale);
  // Error images: white at a fifth of the mean.
  for (const auto& [name, image] : {std::pair<std::string, const RgbImage*>{"radiosity", &radiosity},
                                    std::pair<std::string, const RgbImage*>{"two-pass", &twoPassImage}}) {
    const RgbImage difference = absoluteDifference(*image, reference.B);
    writePfm(difference, a.output + "/error-" + name + ".pfm");
    writePpm(greyOfLargestChannel(difference, 0.2 * mean), 1.0, a.output + "/error-" + name + ".ppm");
  }

  std::printf("path tracer: %dx%d pixels, %d paths each, %.3g rays, %.2f s (%.3g rays/s)\n", a.width,
              a.height, a.paths, static_cast<double>(reference.rays), traceSeconds,
              static_cast<double>(reference.rays) / std::max(traceSeconds, 1e-9));
  std::printf("radiosity: %zu elements, %.2f s; two-pass picture %.2f s\n", solution.mesh.size(),
              solveSeconds, twoPassSeconds);
  std::printf(
      "image,rms_difference,path_tracer_noise,error,error_low_95,error_high_95   (relative to the mean)\n");
  for (const auto& [name, image] : {std::pair<std::string, const RgbImage*>{"radiosity", &radiosity},
                                    std::pair<std::string, const RgbImage*>{"two-pass", &twoPassImage}}) {
    const ImageError e = compareToReference(*image, reference);
    std::printf("%s,%.4f,%.4f,%.4f,%.4f,%.4f\n", name.c_str(), e.rmsDifference, e.referenceNoise, e.error,
                e.low, e.high);
  }
  std::cerr << "images written to " << a.output << "/ (PFM: linear W/m^2; PPM: one exposure for all)\n";
}

}  // namespace

void addComparePtCommand(CLI::App& app) {
  auto a = std::make_shared<CompareArguments>();
  auto* command = app.add_subcommand(
      "compare-pt",
      "The radiosity solution (and the two-pass picture) against the path tracer from the scene's camera: "
      "RMS "
      "error with the path tracer's noise taken out and a 95 % interval; images and error images");
  command->add_option("scene", a->scene, "Scene file (.json or .obj)")->required()->check(CLI::ExistingFile);
  a->solution.add(*command);
  a->camera.add(*command);
  command->add_option("--output", a->output, "Folder for the images")->capture_default_str();
  command->add_option("--width", a->width, "Image width")->capture_default_str()->check(CLI::Range(1, 8192));
  command->add_option("--height", a->height, "Image height")
      ->capture_default_str()
      ->check(CLI::Range(1, 8192));
  command->add_option("--paths", a->paths, "Path-traced samples per pixel")
      ->capture_default_str()
      ->check(CLI::Range(2, 1 << 24));
  command
      ->add_option("--gather-rays", a->gatherRays,
                   "Final-gather rays per gathered pixel of the two-pass picture")
      ->capture_default_str()
      ->check(CLI::Range(16, 1 << 20));
  command
      ->add_option(
          "--gather-spacing", a->gatherSpacing,
          "Gather at every N-th pixel of each row and column of the two-pass picture and interpolate "
          "the gathered light between those on the same surface (the direct light is exact at every "
          "pixel)")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  command->callback([a] { run(*a); });
}

}  // namespace rt::cli
