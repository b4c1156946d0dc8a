// radiosity bench formfactors [--scene S] [--output DIR] [mesh options]: sweeps each method's knob (hemicube
// resolution, raycast samples per pair, montecarlo rays per element, nusselt segments per arc) and measures
// time and error against a reference: "analytic" where nothing can be occluded, otherwise "exact" when that
// method is built in and the mesh is small, else raycast with 1024 samples per pair. Writes
// DIR/formfactors.csv (method,parameter,seconds,rms_error,max_error,row_sum_error), prints the fitted log-log
// slopes, and draws DIR/formfactors.png and .svg when the visualisation library is built in.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "core/formfactor/formfactor_method.h"
#include "core/formfactor/shaft_culling.h"
#include "core/power_law.h"
#ifdef RT_HAVE_VIZ
#include "viz/chart.h"
#endif

namespace rt::cli {
namespace {

struct BenchArguments {
  std::string scene = "scenes/cornell-box.json";
  std::string output = "bench-formfactors";
  MeshArguments mesh;
  std::uint64_t seed = 1;
};

struct Row {
  std::string method;
  int parameter;
  double seconds, rmsError, maxError, rowSumError, relativeRmsError;
};

struct Sweep {
  std::string method;
  std::string knob;
  std::vector<int> values;
};

// The swept value sets the knob the method declares (FormFactorMethod::knob()); a tolerance as its digits.
FormFactorOptions optionsFor(const std::string& method, int value, std::uint64_t seed) {
  FormFactorOptions o;
  o.seed = seed;
  const AccuracyKnob knob = accuracyKnobOf(method);
  return knob.applied(o, knob.fromSweep(value));
}

void run(const BenchArguments& a) {
  const Scene scene = loadSceneReportingWarnings(a.scene);
  MeshOptions meshOptions = a.mesh.options();
  if (!a.mesh.noSubdivide && a.mesh.subdivide == 0 && a.mesh.maxEdge == 0) {
    meshOptions.mode =
        MeshOptions::Mode::Count;  // a few hundred elements for the Cornell box: seconds per run
    meshOptions.count = 3;
  }
  const Mesh mesh = buildMesh(scene, meshOptions);
  const Eigen::VectorXd areas = mesh.areas();
  std::filesystem::create_directories(a.output);
  ProgressLine progress;

  // The reference.
  const bool occludable = ShaftCulling(mesh).anyOccluder();
  const auto names = formFactorMethodNames();
  const bool haveExact = std::find(names.begin(), names.end(), "exact") != names.end();
  std::string referenceMethod = "analytic";
  FormFactorOptions referenceOptions;
  referenceOptions.seed = a.seed;
  if (occludable) {
    if (haveExact && mesh.size() <= 600) {
      referenceMethod = "exact";  // ~30 s at 500 elements to 1e-6
      referenceOptions.tolerance = 1e-6;
    } else {
      referenceMethod = "raycast";
      referenceOptions.samples = 1024;
      // Its own random numbers: with the sweep's seed the sweep's 1024-sample run would be this very matrix.
      referenceOptions.seed = a.seed + 1;
    }
  }
  FormFactorStats referenceStats;
  const FormFactorMatrix reference =
      makeFormFactorMethod(referenceMethod)->compute(mesh, referenceOptions, progress, referenceStats);
  progress.finish();
  const Eigen::VectorXd referenceRows = reference.rowwise().sum();
  std::cout << "scene " << a.scene << ", " << mesh.size() << " elements; reference: " << referenceMethod
            << (referenceMethod == "raycast" ? " (1024 samples/pair)" : "") << ", " << referenceStats.seconds
            << " s\n";

  std::vector<Sweep> sweeps = {{"hemicube", "resolution", {16, 32, 64, 128, 256, 512}},
                               {"raycast", "samples/pair", {1, 4, 16, 64, 256, 1024}},
                               {"montecarlo", "rays/element", {64, 256, 1024, 4096, 16384, 65536}},
                               {"nusselt", "segments/arc", {4, 8, 16, 32, 64}},
                               {"hybrid", "rays per 1 % F", {1, 4, 16, 64, 256}},
                               {"quadrature", "digits (tolerance 10^-d)", {2, 3, 4, 5, 6}}};
  if (occludable) sweeps.push_back({"analytic-visibility", "rays/pair", {1, 4, 16, 64, 256}});

  std::vector<Row> rows;
  for (const Sweep& sweep : sweeps) {
    std::vector<double> parameters, seconds, errors;
    for (int value : sweep.values) {
      FormFactorStats stats;
      const FormFactorMatrix F =
          makeFormFactorMethod(sweep.method)
              ->compute(mesh, optionsFor(sweep.method, value, a.seed), progress, stats);
      progress.finish();
      const FormFactorMatrix difference = F - reference;
      Row row{sweep.method,
              value,
              stats.seconds,
              std::sqrt(difference.squaredNorm() / static_cast<double>(difference.size())),
              difference.cwiseAbs().maxCoeff(),
              (F.rowwise().sum() - referenceRows).cwiseAbs().maxCoeff(),
              difference.norm() / std::max(reference.norm(), 1e-300)};
      rows.push_back(row);
      parameters.push_back(value);
      seconds.push_back(row.seconds);
      errors.push_back(row.rmsError);
      std::printf("%-20s %-14s %6d  %9.3f s  rms %.3e (%.2g %%)  max %.3e  row sums %.3e\n",
                  sweep.method.c_str(), sweep.knob.c_str(), value, row.seconds, row.rmsError,
                  100 * row.relativeRmsError, row.maxError, row.rowSumError);
    }
    std::printf("%-20s slope of log(rms error): %.2f per log(%s), %.2f per log(seconds)\n",
                sweep.method.c_str(), logLogSlope(parameters, errors), sweep.knob.c_str(),
                logLogSlope(seconds, errors));
  }

  const std::string csv = (std::filesystem::path(a.output) / "formfactors.csv").string();
  std::ofstream out(csv);
  out << "method,parameter,seconds,rms_error,max_error,row_sum_error,relative_rms_error\n";
  char line[256];
  for (const Row& r : rows) {
    std::snprintf(line, sizeof line, "%s,%d,%.6g,%.6g,%.6g,%.6g,%.6g\n", r.method.c_str(), r.parameter,
                  r.seconds, r.rmsError, r.maxError, r.rowSumError, r.relativeRmsError);
    out << line;
  }
  if (!out) throw std::runtime_error("cannot write " + csv);
  std::cout << "wrote " << csv << "\n";
#ifdef RT_HAVE_VIZ
  std::vector<viz::Series> series;
  for (const Sweep& sweep : sweeps) {
    viz::Series s;
    s.name = sweep.method;
    for (const Row& r : rows)
      if (r.method == sweep.method && r.rmsError > 0 && r.seconds > 0) {
        s.x.push_back(r.seconds);
        s.y.push_back(r.rmsError);
      }
    series.push_back(s);
  }
  viz::ChartOptions chart;
  chart.title = "Form factors: RMS error against run time (" + std::to_string(mesh.size()) +
                " elements, reference " + referenceMethod + ")";
  chart.xLabel = "seconds";
  chart.yLabel = "RMS error of F";
  chart.logX = chart.logY = true;
  for (const char* extension : {".png", ".svg"}) {
    const std::string path =
        (std::filesystem::path(a.output) / (std::string("formfactors") + extension)).string();
    viz::writeLineChart(series, chart, path);
    std::cout << "wrote " << path << "\n";
  }
#endif
}

}  // namespace

void addBenchFormFactorsCommand(CLI::App& bench) {
  auto arguments = std::make_shared<BenchArguments>();
  auto* command = bench.add_subcommand("formfactors", "Time against error of every form-factor method");
  command->add_option("--scene", arguments->scene, "Scene file")->capture_default_str();
  command->add_option("--output", arguments->output, "Output folder")->capture_default_str();
  command->add_option("--seed", arguments->seed, "Seed of the stochastic methods")->capture_default_str();
  arguments->mesh.add(*command);
  command->callback([arguments] { run(*arguments); });
}

}  // namespace rt::cli
