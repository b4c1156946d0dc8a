// radiosity bench sampling: plain Monte Carlo, the constant control variate and quasi-Monte Carlo (Sobol)
// lines in a line-tracing solver, over a range of ray budgets and several seeds: run time and RMS error
// against the direct solution of F computed by the named method (quadrature unless told), and each
// variant's log-log slope of error against rays and its error at equal rays, the control variate's row sums
// counted -> stdout and DIR/sampling.csv (docs/benchmarks.md).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/setting_options.h"
#include "core/io/scene_loader.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/sampling_study.h"

namespace rt::cli {
namespace {

struct BenchArguments {
  std::string scene = "scenes/cornell-box.json";
  std::string formFactors = "quadrature";
  std::string solver = "local-lines";
  std::string output = "bench-sampling";
  std::vector<long> rays{2000, 8000, 32000, 128000, 512000};
  int seeds = 8;
  double tolerance = 1e-4;
  int iterations = 0;
  std::uint64_t seed = 1;
  MeshArguments mesh;
};

void run(const BenchArguments& a) {
  const Scene scene = loadSceneReportingWarnings(a.scene);
  requireLight(scene);
  MeshOptions meshOptions = a.mesh.options();
  if (!a.mesh.noSubdivide && a.mesh.subdivide == 0 && a.mesh.maxEdge == 0) {
    meshOptions.mode = MeshOptions::Mode::Count;  // the stochastic lesson's mesh of the Cornell box
    meshOptions.count = 3;
  }
  const Mesh mesh = buildMesh(scene, meshOptions);
  ProgressLine progress;
  const FormFactorMatrix F = computeFormFactorsReporting(mesh, a.formFactors, FormFactorOptions{}, progress);
  RgbField reference;
  const SolverStatus status = directSolve(RadiositySystem::fromMesh(mesh, F), reference, {});
  if (status != SolverStatus::Success)
    throw std::runtime_error("the direct reference solve failed: " + toString(status));

  SamplingStudyOptions o;
  o.solver = a.solver;
  o.raysPerIteration = a.rays;
  o.seeds = a.seeds;
  o.base.tolerance = a.tolerance;
  o.base.maxIterations = a.iterations;
  o.base.seed = a.seed;
  const auto series = runSamplingStudy(RadiositySystem::fromGeometry(mesh), reference, o, &progress);
  progress.finish();

  std::filesystem::create_directories(a.output);
  const std::string csvPath = a.output + "/sampling.csv";
  std::ofstream csv(csvPath);
  if (!csv) throw InputError({csvPath}, "cannot write the benchmark table");
  csv << "variant,rays_per_iteration,rays,row_sum_rays,seconds,rms_error,reported_standard_error\n";
  std::printf(
      "scene %s, %zu elements, solver %s (tolerance %g, iteration cap %d), reference: direct solve of F by "
      "%s; %d seeds per point\n",
      a.scene.c_str(), mesh.size(), a.solver.c_str(), a.tolerance, a.iterations, a.formFactors.c_str(),
      a.seeds);
  std::printf("%-18s %12s %12s %12s %10s %12s %12s\n", "variant", "rays/it", "rays", "row sums", "seconds",
              "rms error", "reported SE");
  for (const SamplingSeries& s : series) {
    for (const SamplingPoint& p : s.points) {
      std::printf("%-18s %12ld %12.0f %12.0f %10.4f %12.4e %12.4e\n", s.variant.name.c_str(),
                  p.raysPerIteration, p.rays, p.rowSumRays, p.seconds, p.error, p.standardError);
      char line[200];
      std::snprintf(line, sizeof line, "%s,%ld,%.0f,%.0f,%.6g,%.6g,%.6g\n", s.variant.name.c_str(),
                    p.raysPerIteration, p.rays, p.rowSumRays, p.seconds, p.error, p.standardError);
      csv << line;
    }
  }
  std::printf(
      "\nlog-log slope of rms error against rays; at the largest budget, error over plain Monte Carlo's "
      "at the same rays (row sums included, on its fitted line):\n");
  for (const SamplingSeries& s : series)
    std::printf("  %-18s %7.3f %7.3f\n", s.variant.name.c_str(), s.slope,
                series.empty() ? 0.0 : errorRatioAtEqualRays(series.front(), s));
  std::cerr << "table written to " << csvPath << "\n";
}

}  // namespace

void addBenchSamplingCommand(CLI::App& bench) {
  auto a = std::make_shared<BenchArguments>();
  auto* command = bench.add_subcommand(
      "sampling",
      "Plain Monte Carlo, control variate and quasi-Monte Carlo lines: time and RMS error against the direct "
      "solution over a range of rays, with the log-log slopes -> DIR/sampling.csv");
  command->add_option("--scene", a->scene, "Scene file")->capture_default_str()->check(CLI::ExistingFile);
  a->mesh.add(*command);
  addSettingOption(*command, "method", a->formFactors)
      ->default_str(a->formFactors)
      ->description("The form-factor method of the reference solution");
  addSettingOption(*command, "solver", a->solver)->default_str(a->solver);
  command->add_option("--rays", a->rays, "Rays per iteration, one run per value and seed")
      ->capture_default_str();
  command->add_option("--seeds", a->seeds, "Runs per point (seeds --seed, --seed + 1, ...)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command->add_option("--tolerance", a->tolerance, "The solver's tolerance")->capture_default_str();
  command
      ->add_option("--iterations", a->iterations,
                   "The solver's iteration cap (0: its own); the result of a capped run is measured too")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_option("--seed", a->seed, "The first seed")->capture_default_str();
  command->add_option("--output", a->output, "Output folder")->capture_default_str();
  command->callback([a] {
    try {
      run(*a);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("--solver", e.what());
    }
  });
}

}  // namespace rt::cli
