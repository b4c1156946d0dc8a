// radiosity render: one picture of a scene from its camera (or --camera). By default the two-pass picture:
// the radiosity solution read through a second pass, the emitters' direct light exact at every pixel and one
// gathered bounce from the solution, with no mesh artefacts. --flat shows the solution's elements as they are
// (what the mesh alone gives), --path-trace N the path tracer's picture (no mesh, no solve). PNG at one
// exposure (the mean at 18 % grey, or --exposure), or PFM (linear W/m^2) / PPM.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/output_paths.h"
#include "cli/solution.h"
#include "core/input_error.h"
#include "core/io/scene_loader.h"
#include "core/pathtrace/image_compare.h"
#include "core/pathtrace/path_tracer.h"
#include "core/pathtrace/two_pass.h"
#ifdef RT_HAVE_VIZ
#include "viz/image_png.h"
#endif

namespace rt::cli {
namespace {

struct RenderArguments {
  std::string scene;
  std::string output;
  CameraArgument camera;
  SolutionArguments solution;
  int width = 512, height = 512;
  int gatherRays = 1024;  // per gathered pixel
  int gatherSpacing = 8;  // gather at every this many pixels of a row and column
  int pathTrace = 0;      // paths per pixel; 0: the two-pass picture
  bool flat = false;
  double exposure = 0;  // 0: the mean at 18 % grey
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void write(const RgbImage& image, double exposure, const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  const double scale = exposure > 0 ? exposure : middleGreyScale(image);
  if (extension == ".pfm") {
    writePfm(image, path);
  } else if (extension == ".ppm") {
    writePpm(image, scale, path);
  } else if (extension == ".png") {
#ifdef RT_HAVE_VIZ
    viz::writeRgbImagePng(image, scale, path);
#else
    throw InputError({"--output"}, "PNG needs the build with VTK; write .pfm or .ppm");
#endif
  } else {
    throw InputError({"--output"}, "'" + path + "': the picture is written as .png, .pfm or .ppm");
  }
}

void run(const RenderArguments& a) {
  const auto start = std::chrono::steady_clock::now();
  const std::string extension = std::filesystem::path(a.output).extension().string();
  if (extension != ".png" && extension != ".pfm" && extension != ".ppm")
    throw InputError({"--output"}, "'" + a.output + "': the picture is written as .png, .pfm or .ppm");
  checkOutputPaths({a.output});
  Scene scene = loadSceneReportingWarnings(a.scene);
  a.camera.applyTo(scene);
  requireLight(scene);
  const Camera camera = scene.cameraOrDefault();
  RgbImage image;
  if (a.pathTrace > 0) {
    const PathTracer tracer(scene);
    PathTraceOptions options;
    options.samples = a.pathTrace;
    options.seed = a.solution.seed;
    image = tracer.render(camera, a.width, a.height, options).B;
    std::fprintf(stderr, "path tracer: %dx%d pixels, %d paths each, %.3g rays, %.2f s\n", a.width, a.height,
                 a.pathTrace, static_cast<double>(tracer.raysCast()), secondsSince(start));
  } else {
    Pipeline pipeline;
    const Solution solution = solveOnMesh(scene, a.solution, pipeline);
    const double solved = secondsSince(start);
    if (a.flat) {
      const RayScene rays(solution.mesh);
      image = renderElements(solution.mesh, solution.outcome.B, rays, camera, a.width, a.height);
    } else {
      const TracingScene tracing(scene);
      const TwoPass twoPass(tracing, solution.mesh, solution.outcome.B,
                            solution.formFactors ? &solution.formFactors->F : nullptr);
      TwoPassOptions options;
      options.gatherRays = a.gatherRays;
      options.seed = a.solution.seed;
      image = twoPass.render(camera, a.width, a.height, options, a.gatherSpacing);
    }
    std::fprintf(stderr, "%s picture: %dx%d pixels, solution (%zu elements) %.2f s, picture %.2f s\n",
                 a.flat ? "flat" : "two-pass", a.width, a.height, solution.mesh.size(), solved,
                 secondsSince(start) - solved);
  }
  write(image, a.exposure, a.output);
  std::cerr << "picture written to " << a.output << "\n";
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto a = std::make_shared<RenderArguments>();
  auto* command = app.add_subcommand(
      "render",
      "One picture from the scene's camera: the two-pass picture (direct light exact at every pixel, one "
      "gathered bounce from the radiosity solution), the solution's flat elements (--flat) or the path "
      "tracer's (--path-trace N)");
  command->add_option("scene", a->scene, "Scene file (.json or .obj)")->required()->check(CLI::ExistingFile);
  command->add_option("--output", a->output, "The picture: .png (one exposure), .pfm (linear W/m^2) or .ppm")
      ->required();
  a->solution.add(*command);
  a->camera.add(*command);
  command->add_option("--width", a->width, "Image width")->capture_default_str()->check(CLI::Range(1, 8192));
  command->add_option("--height", a->height, "Image height")
      ->capture_default_str()
      ->check(CLI::Range(1, 8192));
  command->add_option("--gather-rays", a->gatherRays, "Final-gather rays per gathered pixel")
      ->capture_default_str()
      ->check(CLI::Range(16, 1 << 20));
  command
      ->add_option("--gather-spacing", a->gatherSpacing,
                   "Gather at every N-th pixel of each row and column and interpolate the gathered light "
                   "between those on the same surface (the direct light is exact at every pixel)")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  auto* traced = command
                     ->add_option("--path-trace", a->pathTrace,
                                  "The path tracer's picture with this many paths per pixel instead")
                     ->check(CLI::Range(1, 1 << 24));
  command->add_flag("--flat", a->flat, "The solution's elements as they are, with no second pass")
      ->excludes(traced);
  command
      ->add_option(
          "--exposure", a->exposure,
          "PNG and PPM: multiply W/m^2 by this before clamping to white (default: the mean at 18 % grey)")
      ->check(CLI::PositiveNumber);
  command->callback([a] { run(*a); });
}

}  // namespace rt::cli
