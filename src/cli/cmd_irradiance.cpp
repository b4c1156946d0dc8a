// radiosity irradiance: H and B at the user's points, by the two-pass method (the radiosity solution of
// `solve`, direct light computed at the point, one final gather), or by the path tracer (--path-trace N).
#include <chrono>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/output_paths.h"
#include "cli/point_query.h"
#include "cli/solution.h"
#include "core/io/point_csv.h"
#include "core/io/scene_loader.h"
#include "core/pathtrace/path_tracer.h"
#include "core/pathtrace/two_pass.h"

namespace rt::cli {
namespace {

struct IrradianceArguments {
  std::string scene;
  std::string points;
  std::string output;
  PointQuery query;         // the two-pass method's settings, mesh error and target error
  std::string targetError;  // --target-error as written ("0.5%" or 0.005)
  int pathTrace = 0;        // paths per point; 0: the two-pass method
  bool breakdown = false;   // write H's parts: direct, first bounce, the rest
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void run(const IrradianceArguments& a) {
  const auto start = std::chrono::steady_clock::now();
  checkOutputPaths({a.output});
  const Scene scene = loadSceneReportingWarnings(a.scene);
  requireLight(scene);
  const std::vector<SurfacePoint> points = readSurfacePoints(a.points);
  const TracingScene tracing(scene);
  std::vector<PointEstimate> estimates;
  if (a.pathTrace > 0) {
    PathTracer tracer(scene);
    PathTraceOptions options;
    options.samples = a.pathTrace;
    options.seed = a.query.solution.seed;
    estimates = tracer.estimate(points, options);
    std::fprintf(stderr, "path tracing: %zu points x %d paths, %.3g rays, %.2f s\n", points.size(),
                 a.pathTrace, static_cast<double>(tracer.raysCast()), secondsSince(start));
  } else {
    const MeshOptions mesh = a.query.solution.mesh.optionsFor(scene);
    estimates = a.query.targetError > 0 ? estimatesForTarget(scene, tracing, mesh, a.query, points)
                                        : estimatesWithMeshError(scene, tracing, mesh, a.query, points);
  }
  std::vector<std::string> surfaces(points.size());
  std::size_t nowhere = 0, first = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (estimates[p].element >= 0) {
      surfaces[p] =
          scene
              .surfaces[static_cast<std::size_t>(
                  scene.patches[static_cast<std::size_t>(tracing.patchOf(estimates[p].element))].surface)]
              .name;
    } else if (nowhere++ == 0) {
      first = p;
    }
  }
  if (nowhere > 0)
    std::cerr << "warning: " << nowhere
              << " point(s) lie on no surface facing their normal (the first is point " << first + 1
              << ", line " << first + 2 << " of " << a.points
              << " if the file has no blank lines): their B is written as 0\n";
  writePointEstimates(a.output, points, estimates, surfaces, a.breakdown, a.query.targetError > 0);
  std::cerr << "irradiance written to " << a.output << " (" << secondsSince(start) << " s in all)\n";
}

}  // namespace

void addIrradianceCommand(CLI::App& app) {
  auto a = std::make_shared<IrradianceArguments>();
  auto* command = app.add_subcommand(
      "irradiance",
      "Irradiance H and radiosity B at given points (CSV x,y,z,nx,ny,nz) by the two-pass method: the "
      "radiosity "
      "solution, direct light computed at each point, one final gather; or by path tracing");
  command->add_option("scene", a->scene, "Scene file (.json or .obj)")->required()->check(CLI::ExistingFile);
  command->add_option("--points", a->points, "CSV of points: header x,y,z,nx,ny,nz, one point per line")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("--output", a->output,
                   "CSV, one row per point in order: x,y,z,nx,ny,nz,surface,H_r,H_g,H_b,B_r,B_g,B_b, the "
                   "standard error of each (H_r_error...) and the estimate of the mesh's error "
                   "(H_r_mesh_error...)")
      ->required();
  a->query.solution.add(*command);
  auto* gatherRays =
      command->add_option("--gather-rays", a->query.twoPass.gatherRays, "Final-gather rays per point")
          ->capture_default_str()
          ->check(CLI::Range(16, 1 << 24));
  command
      ->add_option("--shadow-rays", a->query.twoPass.shadowRays,
                   "Shadow rays per point and emitter, only where the shaft test finds a possible blocker")
      ->capture_default_str()
      ->check(CLI::Range(16, 1 << 20));
  command
      ->add_option("--near-factor", a->query.twoPass.nearFactor,
                   "Gather hits closer than this many element sizes gather their indirect light anew, one "
                   "bounce further on (default: every hit)")
      ->check(CLI::Range(0.0, std::numeric_limits<double>::infinity()));
  command->add_option("--near-rays", a->query.twoPass.nearRays, "Rays of that secondary gather")
      ->capture_default_str()
      ->check(CLI::Range(1, 1 << 16));
  command->add_flag(
      "!--no-mesh-error", a->query.meshError,
      "Skip the mesh-error estimate (by default the points are computed a second time on a mesh with "
      "elements twice the size, and the difference is written as H_r_mesh_error...)");
  command->add_flag(
      "--breakdown", a->breakdown,
      "Also write H in parts by the bounces its light took: H_r_direct... (none), H_r_bounce... (one: for "
      "the two-pass method the direct light at its gather's hits), H_r_rest... (the rest), with the standard "
      "errors of the first two; against a path-traced reference with the same columns they show where an "
      "error comes from");
  auto* target =
      command
          ->add_option(
              "--target-error", a->targetError,
              "Choose the effort for this RMS error of H relative to H (0.5% or 0.005): a pilot pass "
              "measures the noise and the mesh error, the mesh is refined while its error is over 0.6 "
              "of the target, and the gather rays are set for the rest; the estimate (two standard "
              "errors plus the mesh error) is written as H_r_estimate...")
          ->check([](const std::string& text) {
            return parseTargetError(text) > 0 ? std::string()
                                              : "not a relative error in (0, 1): 0.5% or 0.005";
          });
  auto* pathTrace =
      command
          ->add_option(
              "--path-trace", a->pathTrace,
              "Path-trace each point with this many paths instead (no mesh, no solve: the reference)")
          ->check(CLI::Range(32, 1 << 30));
  target->excludes(gatherRays)->excludes(pathTrace);
  command->callback([a] {
    if (!a->targetError.empty()) a->query.targetError = parseTargetError(a->targetError);
    run(*a);
  });
}

}  // namespace rt::cli
