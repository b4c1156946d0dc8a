// radiosity bench solvers: every solver on one scene, error against the direct solution after every
// iteration, as a function of time and of iterations -> DIR/solvers.csv, a summary on stdout, and charts (PNG
// and SVG) when the visualisation library is built in.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/setting_options.h"
#include "core/formfactor/formfactor_method.h"
#include "core/io/scene_loader.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/solver.h"
#include "core/solvers/solver_support.h"
#ifdef RT_HAVE_VIZ
#include "viz/chart.h"
#endif

namespace rt::cli {
namespace {

struct BenchArguments {
  std::string scene = "scenes/cornell-box.json";
  std::string formFactors = defaultFormFactorMethod();
  std::string output = "bench-solvers";
  double tolerance = 1e-10;
  std::uint64_t seed = 1;
  MeshArguments mesh;
};

struct Sample {
  int iteration;
  double seconds;
  long rays;
  double error;
  double residual;
};

// Caps chosen so that every solver can get below 1e-6 where it is able to, in a bench that runs in seconds.
SolverOptions optionsFor(const std::string& name, std::size_t n, const BenchArguments& a) {
  SolverOptions o;
  o.tolerance = a.tolerance;
  o.seed = a.seed;
  o.recordHistory = false;
  o.maxIterations = 2000;
  if (name == "southwell" || name == "progressive") {
    o.maxIterations = static_cast<int>(200 * n);
    o.residualEvery = static_cast<int>(n);  // an O(n^2) residual per O(n) shot would dominate the timing
  }
  if (name == "progressive") o.ambient = true;
  if (name == "stochastic-jacobi" || name == "local-lines") o.tolerance = 1e-8;
  if (name == "local-lines-regular") o.tolerance = 2e-3;  // burn-in bound, then the mean's standard error
  if (name.rfind("random-walk", 0) == 0) {
    o.tolerance = 1e-4;  // relative standard error
    o.maxIterations = 60;
  }
  return o;
}

// First sample at or below the threshold, as "seconds / iterations" text.
std::string firstBelow(const std::vector<Sample>& samples, double threshold) {
  for (const Sample& s : samples) {
    if (s.error <= threshold) {
      char text[96];
      std::snprintf(text, sizeof text, "%.4g s / %d it", s.seconds, s.iteration);
      return text;
    }
  }
  return "not reached";
}

void run(const BenchArguments& a) {
  const Scene scene = loadSceneReportingWarnings(a.scene);
  requireLight(scene);
  MeshOptions meshOptions = a.mesh.options();
  if (!a.mesh.noSubdivide && a.mesh.subdivide == 0 && a.mesh.maxEdge == 0) {
    meshOptions.mode =
        MeshOptions::Mode::Count;  // a default that gives a few hundred elements for the Cornell box
    meshOptions.count = 4;
  }
  const Mesh mesh = buildMesh(scene, meshOptions);
  ProgressLine progress;
  const FormFactorMatrix F = computeFormFactorsReporting(mesh, a.formFactors, FormFactorOptions{}, progress);
  const RadiositySystem system = RadiositySystem::fromMesh(mesh, F);

  RgbField reference;
  const SolverStatus referenceStatus = directSolve(system, reference, {});
  if (referenceStatus != SolverStatus::Success)
    throw std::runtime_error("the direct reference solve failed: " + toString(referenceStatus));
  // Errors by area, as the stochastic solvers report their standard error (relativeAreaRms), so that the
  // noise table's two columns measure the same thing.
  auto errorOf = [&](const RgbField& B) {
    return solver_detail::relativeAreaRms(B - reference, reference, system.areas);
  };

  std::filesystem::create_directories(a.output);
  const std::string csvPath = a.output + "/solvers.csv";
  std::ofstream csv(csvPath);
  if (!csv) throw InputError({csvPath}, "cannot write the benchmark table");
  csv << "solver,iteration,seconds,rays,relative_error,residual\n";

  std::printf("scene %s, %zu elements, form factors %s\n", a.scene.c_str(), mesh.size(),
              a.formFactors.c_str());
  std::printf("%-18s %-15s %8s %10s %12s  %-22s %-22s\n", "solver", "status", "its", "seconds", "final error",
              "error <= 1e-2", "error <= 1e-6");
  std::map<std::string, std::vector<Sample>> all;
  for (const std::string& name : solverNames()) {
    auto solver = makeSolver(name);
    solver->setOptions(optionsFor(name, mesh.size(), a));
    std::vector<Sample>& samples = all[name];
    solver->setObserver([&](const IterationRecord& r) {
      samples.push_back({r.iteration, r.seconds, r.rays, errorOf(r.B), r.residual});
    });
    const RgbField B = solver->compute(system).solve();
    char line[160];
    for (const Sample& s : samples) {
      std::snprintf(line, sizeof line, "%s,%d,%.9g,%ld,%.9g,%.9g\n", name.c_str(), s.iteration, s.seconds,
                    s.rays, s.error, s.residual);
      csv << line;
    }
    const double seconds = samples.empty() ? 0.0 : samples.back().seconds;
    std::printf("%-18s %-15s %8d %10.4g %12.3e  %-22s %-22s\n", name.c_str(),
                toString(solver->info()).c_str(), solver->iterations(), seconds, errorOf(B),
                firstBelow(samples, 1e-2).c_str(), firstBelow(samples, 1e-6).c_str());
    std::fflush(stdout);
  }
  std::cerr << "table written to " << csvPath << "\n";

  // Noise of stochastic Jacobi against its ray budget: the error should fall like 1 / sqrt(rays).
  const std::string noisePath = a.output + "/stochastic.csv";
  std::ofstream noise(noisePath);
  noise << "rays_per_iteration,total_rays,seconds,relative_error,reported_standard_error\n";
  std::printf("\nstochastic-jacobi noise against rays (tolerance 1e-8 on the unshot power)\n");
  std::printf("%12s %12s %10s %14s %14s\n", "rays/it", "total rays", "seconds", "error", "reported SE");
  for (long budget : {10L, 100L, 1000L, 10000L}) {
    auto solver = makeSolver("stochastic-jacobi");
    SolverOptions o = optionsFor("stochastic-jacobi", mesh.size(), a);
    o.raysPerIteration = budget * static_cast<long>(mesh.size());
    solver->setOptions(o);
    long rays = 0;
    double seconds = 0, reported = 0;
    solver->setObserver([&](const IterationRecord& r) {
      rays = r.rays;
      seconds = r.seconds;
      reported = r.standardError;
    });
    const RgbField B = solver->compute(system).solve();
    const double error = errorOf(B);
    noise << o.raysPerIteration << ',' << rays << ',' << seconds << ',' << error << ',' << reported << '\n';
    std::printf("%12ld %12ld %10.4g %14.4e %14.4e\n", o.raysPerIteration, rays, seconds, error, reported);
  }
  std::cerr << "noise table written to " << noisePath << "\n";

#ifdef RT_HAVE_VIZ
  std::vector<viz::Series> byTime, byIteration;
  for (const auto& [name, samples] : all) {
    viz::Series t{name, {}, {}}, k{name, {}, {}};
    for (const Sample& s : samples) {
      if (!(s.error > 0)) continue;  // log axis
      t.x.push_back(std::max(s.seconds, 1e-6));
      t.y.push_back(s.error);
      k.x.push_back(s.iteration);
      k.y.push_back(s.error);
    }
    byTime.push_back(t);
    byIteration.push_back(k);
  }
  viz::ChartOptions time{"Error against the direct solution vs time", "seconds", "relative error", true,
                         true};
  viz::ChartOptions iterations{"Error against the direct solution vs iterations",
                               "iterations (sweeps, shots, batches)", "relative error", true, true};
  for (const std::string ext : {".png", ".svg"}) {
    viz::writeLineChart(byTime, time, a.output + "/solvers_error_vs_time" + ext);
    viz::writeLineChart(byIteration, iterations, a.output + "/solvers_error_vs_iterations" + ext);
  }
  std::cerr << "charts written to " << a.output << "/solvers_error_vs_{time,iterations}.{png,svg}\n";
#else
  std::cerr << "charts skipped: built without the visualisation library\n";
#endif
}

}  // namespace

void addBenchSolversCommand(CLI::App& bench) {
  auto a = std::make_shared<BenchArguments>();
  auto* command = bench.add_subcommand("solvers",
                                       "Every solver: error against the direct solution vs time and "
                                       "iterations -> DIR/solvers.csv and charts");
  command->add_option("--scene", a->scene, "Scene file")->capture_default_str()->check(CLI::ExistingFile);
  a->mesh.add(*command);
  auto* method = addSettingOption(*command, "method", a->formFactors)->default_str(a->formFactors);
  addDeprecatedAlias(*command, "--formfactors", method);
  command->add_option("--output", a->output, "Output folder")->capture_default_str();
  command->add_option("--tolerance", a->tolerance, "Tolerance of the deterministic solvers")
      ->capture_default_str();
  command->add_option("--seed", a->seed, "Seed of the stochastic solvers")->capture_default_str();
  command->callback([a] { run(*a); });
}

}  // namespace rt::cli
