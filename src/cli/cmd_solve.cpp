// radiosity solve: scene -> mesh -> form factors -> solver -> B.csv and/or an image.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/output_paths.h"
#include "cli/setting_options.h"
#include "core/formfactor/formfactor_method.h"
#include "core/io/scene_loader.h"
#include "core/pipeline/pipeline.h"
#include "core/refine/refine.h"
#include "core/solvers/row_providers.h"
#include "core/solvers/shooting_solvers.h"
#include "core/solvers/solver.h"
#include "lesson/lesson_parser.h"
#ifdef RT_HAVE_VIZ
#include "viz/display_pipeline.h"
#include "viz/scene_image.h"
#endif

namespace rt::cli {
namespace {

struct SolveArguments {
  std::string scene;
  std::string solver;                                   // empty: chosen by size
  std::string formFactors = defaultFormFactorMethod();  // handles occluders
  double tolerance = 1e-6;
  int maxIterations = 0;  // automatic
  std::uint64_t seed = 1;
  int raysPerIteration = 0;  // stochastic solvers; 0 = automatic
  int resolution = 128;
  int samples = 16;
  std::string output;
  std::string image;
  int width = 1024, height = 1024;
  double exposure = 0.0;
  std::string toneMap = "linear";
  bool smooth = false;
  bool edges = false;
  bool verbose = false;
  bool ambient = false;
  // Shooting without the n x n matrix: each shooter's row of F is computed when it shoots.
  bool noMatrix = false;
  bool formFactorsGiven = false;
  std::string legacyFormFactors;  // --formfactors, the old spelling of --method
  MeshArguments mesh;
  // Refining meshers (docs/meshing.md): empty = the uniform mesh of MeshArguments.
  std::string refineMode;
  RefineOptions refine;
};

void writeRadiosityCsv(const Scene& scene, const Mesh& mesh, const RgbField& B, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw InputError({path}, "cannot write the radiosity file");
  out << "element,patch,surface,area,B_r,B_g,B_b\n";
  char line[512];
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Element& e = mesh.elements[i];
    const auto r = static_cast<Eigen::Index>(i);
    std::snprintf(line, sizeof line, "%zu,%d,%s,%.17g,%.17g,%.17g,%.17g\n", i, e.patch,
                  scene.surfaces[scene.patches[e.patch].surface].name.c_str(), e.area, B(r, 0), B(r, 1),
                  B(r, 2));
    out << line;
  }
  if (!out) throw InputError({path}, "error while writing the radiosity file");
}

void writeImage(const SolveArguments& a, const Scene& scene, const Mesh& mesh, const RgbField& B) {
#ifdef RT_HAVE_VIZ
  viz::ImageOptions image;
  image.width = a.width;
  image.height = a.height;
  image.exposure = a.exposure;
  image.toneMap = viz::toneMapFromName(a.toneMap);
  image.smooth = a.smooth;
  image.showEdges = a.edges;
  viz::renderRadiosityImage(mesh, B, scene.cameraOrDefault(), image, a.image);
  std::cerr << "image written to " << a.image << "\n";
#else
  throw std::runtime_error("--image needs the visualisation library (configure with RT_BUILD_VIZ=ON)");
#endif
}

// --mesh adaptive|discontinuity|hierarchical: the refining solvers build their own mesh and form factors.
void runRefined(const SolveArguments& a, const Scene& scene) {
  RefineOptions options = a.refine;
  options.mode = refineModeFromString(a.refineMode);
  options.solverTolerance = a.tolerance;
  ProgressLine progress(true);
  const RefinedSolution solution = solveRefined(scene, options, progress);
  progress.finish();
  std::cerr << "mesh (" << a.refineMode << "): " << solution.stats.summary() << "\n";
  if (!a.output.empty()) {
    writeRadiosityCsv(scene, solution.mesh, solution.B, a.output);
    std::cerr << "radiosity written to " << a.output << "\n";
  }
  if (!a.image.empty()) writeImage(a, scene, solution.mesh, solution.B);
}

// Status check and outputs shared by both ways of solving.
void finish(const SolveArguments& a, const Scene& scene, const Mesh& mesh, SolverStatus status, double error,
            int iterations, const RgbField& B) {
  if (status == SolverStatus::NoConvergence)
    std::cerr << "warning: not converged: the iteration cap ("
              << (a.maxIterations > 0 ? "--iterations " + std::to_string(a.maxIterations)
                                      : std::to_string(iterations) + ", automatic; --iterations raises it")
              << ") was reached with relative residual " << error << "\n";
  if (status != SolverStatus::Success && status != SolverStatus::NoConvergence)
    throw std::runtime_error("the solver failed: " + toString(status));
  if (!a.output.empty()) {
    writeRadiosityCsv(scene, mesh, B, a.output);
    std::cerr << "radiosity written to " << a.output << "\n";
  }
  if (!a.image.empty()) writeImage(a, scene, mesh, B);
}

SolverOptions solverOptions(const SolveArguments& a) {
  SolverOptions options;
  options.tolerance = a.tolerance;
  options.maxIterations = a.maxIterations;
  options.seed = a.seed;
  options.raysPerIteration = a.raysPerIteration;
  options.ambient = a.ambient;
  options.recordHistory = false;
  return options;
}

// --verbose: one line per iteration.
void printIteration(const IterationRecord& r) {
  std::fprintf(stderr, "iteration %d: residual %.6e, unshot power %.6e%s\n", r.iteration, r.residual,
               r.unshotPower, r.shooter >= 0 ? (", shooter " + std::to_string(r.shooter)).c_str() : "");
}

// --no-matrix: the shooting solvers ask for the shooter's row of F when it shoots; nothing n x n is stored.
const char* noMatrixProblem(const std::string& solverName, const std::string& formFactors) {
  if (!solverNeedsMatrix(solverName)) return nullptr;  // it traces rays: there is no matrix anyway
  if (solverName != "southwell" && solverName != "progressive")
    return "--no-matrix needs a shooting solver: --solver southwell or --solver progressive";
  const auto methods = rowProviderMethods();
  if (std::find(methods.begin(), methods.end(), formFactors) == methods.end())
    return "--no-matrix computes rows at the shooter: --method hemicube or --method raycast";
  return nullptr;
}

// A solver that traces its own rays (local-lines): no form factor is computed or stored.
void runWithoutFormFactors(const SolveArguments& a, const Scene& scene, const Mesh& mesh,
                           const std::string& name, ProgressLine& progress) {
  std::cerr << "form factors: none (" << name << " traces rays through the " << mesh.size()
            << " elements; no matrix stored)\n";
  const SolveOutcome outcome =
      solveRadiosity(RadiositySystem::fromGeometry(mesh), name, solverOptions(a), false, progress,
                     a.verbose ? std::function<void(const IterationRecord&)>(printIteration)
                               : std::function<void(const IterationRecord&)>());
  progress.finish();
  std::cerr << "solve (" << name << "): " << toString(outcome.status) << " after " << outcome.iterations
            << " " << (outcome.iterations == 1 ? "iteration" : "iterations") << ", " << outcome.rays
            << " rays, unshot residual " << outcome.error << ", relative standard error "
            << outcome.standardError << "\n";
  finish(a, scene, mesh, outcome.status, outcome.error, outcome.iterations, outcome.B);
}

void run(const SolveArguments& a) {
  checkOutputPaths({a.output, a.image});  // before the expensive part, not after it
  const Scene scene = loadSceneReportingWarnings(a.scene);
  requireLight(scene);
  if (!a.refineMode.empty()) return runRefined(a, scene);
  const std::string solverName = !a.solver.empty() ? a.solver
                                 : a.noMatrix      ? std::string("southwell")
                                                   : std::string();
  const std::string formFactors = a.noMatrix && !a.formFactorsGiven ? std::string("hemicube") : a.formFactors;
  if (!solverName.empty()) makeSolver(solverName);  // an unknown name fails before the expensive part
  if (a.noMatrix)
    if (const char* problem = noMatrixProblem(solverName, formFactors)) throw CLI::ValidationError(problem);
  const Mesh mesh = buildMesh(scene, a.mesh.optionsFor(scene));
  ProgressLine progress(!a.verbose);

  FormFactorOptions ffOptions;
  ffOptions.hemicubeResolution = a.resolution;
  ffOptions.samples = a.samples;
  ffOptions.seed = a.seed;
  std::string name = solverName;
  if (name.empty() && !a.formFactorsGiven) {
    const AutomaticSolve chosen = chooseAutomaticSolve(mesh.size());
    std::cerr << "solver: none named: " << chosen.solver << " for " << chosen.why
              << " (--solver and --method: your own)\n";
    name = chosen.solver;
  } else if (name.empty()) {
    name = chooseSolver(mesh.size());
  }
  if (!solverNeedsMatrix(name)) return runWithoutFormFactors(a, scene, mesh, name, progress);
  if (a.noMatrix) {
    RadiositySystem system;
    system.reflectance = mesh.reflectance;
    system.emission = mesh.emission;
    system.areas = mesh.areas();
    std::cerr << "form factors (" << formFactors << "): one row per shot, no matrix stored\n";
    auto solver = makeSolver(name);
    solver->setOptions(solverOptions(a));
    solver->setProgress(&progress);
    if (a.verbose) solver->setObserver(printIteration);
    std::size_t rows = 0;
    const FormFactorRowProvider provider = makeRowProvider(formFactors, mesh, ffOptions);
    dynamic_cast<ShootingSolver&>(*solver).setRowProvider([&rows, provider](int i, Eigen::VectorXd& row) {
      ++rows;
      provider(i, row);
    });
    const RgbField B = solver->compute(system).solve();
    progress.finish();
    std::cerr << "solve (" << name << ", rows on demand): " << toString(solver->info()) << " after "
              << solver->iterations() << " shots, " << rows << " rows computed, unshot residual "
              << solver->error() << "\n";
    finish(a, scene, mesh, solver->info(), solver->error(), solver->iterations(), B);
    return;
  }
  // The pipeline's form factors and solve, as the lessons and the app compute them.
  Pipeline pipeline;
  const auto cached = pipeline.formFactors(mesh, formFactors, ffOptions, progress);
  progress.finish();
  reportFormFactorStats(std::cerr, formFactors, cached->stats);
  const SolveOutcome outcome =
      solveRadiosity(RadiositySystem::fromMesh(mesh, cached->F), name, solverOptions(a), false, progress,
                     a.verbose ? std::function<void(const IterationRecord&)>(printIteration)
                               : std::function<void(const IterationRecord&)>());
  progress.finish();
  std::cerr << "solve (" << name << "): " << toString(outcome.status) << " after " << outcome.iterations
            << " " << (outcome.iterations == 1 ? "iteration" : "iterations") << ", relative residual "
            << outcome.residual << "\n";
  finish(a, scene, mesh, outcome.status, outcome.error, outcome.iterations, outcome.B);
}

}  // namespace

void addSolveCommand(CLI::App& app) {
  auto a = std::make_shared<SolveArguments>();
  auto* command =
      app.add_subcommand("solve", "Solve the radiosity system of a scene; write B.csv and/or an image");
  command->add_option("scene", a->scene, "Scene file (.json or .obj)")->required()->check(CLI::ExistingFile);
  addSettingOption(*command, "solver", a->solver)
      ->default_str(
          "by size: direct below 3,000 elements, local-lines above (gauss-seidel when --method is given)");
  auto* formFactors =
      addSettingOption(*command, "method", a->formFactors)->default_str(defaultFormFactorMethod());
  // It used to name the solver: a solver's name is still taken (with a note), anything else is checked below.
  formFactors->get_validator(kTableCheck)->active(false);
  // The old spelling of the form-factor method, kept apart: old command lines put the solver in --method.
  command
      ->add_option_function<std::string>(
          "--formfactors",
          [a](const std::string& value) {
            std::cerr << "radiosity: --formfactors is deprecated, use --method\n";
            a->legacyFormFactors = value;
          },
          "Deprecated spelling of --method")
      ->group("");
  addSettingOption(*command, "tolerance", a->tolerance);
  addDeprecatedAlias(*command, "--max-iterations",
                     addSettingOption(*command, "iterations", a->maxIterations));
  addSettingOption(*command, "seed", a->seed);
  addSettingOption(*command, "rays-per-iteration", a->raysPerIteration);
  addSettingOption(*command, "resolution", a->resolution);
  addSettingOption(*command, "samples", a->samples);
  command->add_flag("--ambient", a->ambient, "progressive: show B plus the ambient term");
  command->add_flag("--no-matrix", a->noMatrix,
                    "southwell/progressive: compute each shooter's row of F when it shoots (--formfactors "
                    "hemicube, the default here, or raycast) instead of storing the n x n matrix");
  a->mesh.add(*command);
  command->add_option("--output", a->output,
                      "Write B per element as CSV (element,patch,surface,area,B_r,B_g,B_b)");
  command->add_option("--image", a->image,
                      "Render the solved scene from its camera to a PNG (needs an X server)");
  command->add_option("--width", a->width, "Image width")->capture_default_str();
  command->add_option("--height", a->height, "Image height")->capture_default_str();
  addSettingOption(*command, "exposure", a->exposure);
  addDeprecatedAlias(*command, "--tonemap", addSettingOption(*command, "tone-map", a->toneMap));
  addSettingFlag(*command, "smooth", a->smooth);
  addSettingFlag(*command, "edges", a->edges);
  command->add_option("--mesh", a->refineMode, "Refining mesher instead of a uniform mesh (docs/meshing.md)")
      ->check(CLI::IsMember({"uniform", "adaptive", "discontinuity", "hierarchical"}));
  command->add_option("--initial-edge", a->refine.initialMaxEdge,
                      "--mesh: starting max edge (0 = diagonal / 5)");
  command->add_option("--min-edge", a->refine.minEdge, "--mesh: smallest edge refinement may make");
  command->add_option("--gradient-tolerance", a->refine.gradientTolerance, "--mesh adaptive: split threshold")
      ->capture_default_str();
  command->add_option("--passes", a->refine.maxPasses, "--mesh adaptive: solves")->capture_default_str();
  command->add_option("--max-elements", a->refine.maxElements, "--mesh adaptive: element budget")
      ->capture_default_str();
  command->add_option("--link-tolerance", a->refine.linkTolerance, "--mesh hierarchical: link threshold")
      ->capture_default_str();
  command->add_option("--rays", a->refine.visibilitySamples, "--mesh: visibility rays per pair or link")
      ->capture_default_str();
  command->add_flag("--verbose", a->verbose, "One line per iteration instead of a progress line");
  command->callback([a, formFactors] {
    a->formFactorsGiven = formFactors->count() > 0;
    // `solve --method` used to name the solver: a solver's name there still works, with a note.
    const auto& methods = lesson::knownMethods();
    if (!isSolverName(a->formFactors) &&
        std::find(methods.begin(), methods.end(), a->formFactors) == methods.end())
      throw CLI::ValidationError("--method", "unknown form-factor method '" + a->formFactors + "'");
    if (isSolverName(a->formFactors)) {
      std::cerr << "radiosity: --method names the form-factor method now; use --solver " << a->formFactors
                << "\n";
      a->solver = a->formFactors;
      a->formFactors = defaultFormFactorMethod();
      a->formFactorsGiven = false;
    }
    if (!a->legacyFormFactors.empty()) {
      a->formFactors = a->legacyFormFactors;
      a->formFactorsGiven = true;
    }
    run(*a);
  });
}

}  // namespace rt::cli
