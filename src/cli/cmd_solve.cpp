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
#include "cli/solution.h"
#include "core/formfactor/formfactor_method.h"
#include "core/io/ply_export.h"
#include "core/io/radiosity_csv.h"
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
#include "viz/vertex_interpolation.h"
#endif

namespace rt::cli {
namespace {

struct SolveArguments {
  std::string scene;
  SolutionArguments s;  // mesh, form factors, solver: shared with the commands built on a solution
  std::string output;
  std::string ply;
  std::string nodes;  // a linear basis's node values as CSV
  std::string image;
  CameraArgument camera;
  int width = 1024, height = 1024;
  double exposure = 0.0;
  std::string toneMap = "linear";
  bool smooth = false;
  bool edges = false;
  // Shooting without the n x n matrix: each shooter's row of F is computed when it shoots.
  bool noMatrix = false;
  bool formFactorsGiven = false;
  std::string legacyFormFactors;  // --formfactors, the old spelling of --method
  // Refining meshers (docs/meshing.md): empty = the uniform mesh of MeshArguments.
  std::string refineMode;
  RefineOptions refine;
};

void writeRadiosityCsv(const Scene& scene, const Mesh& mesh, const RgbField& B, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw InputError({path}, "cannot write the radiosity file");
  out << radiosityCsv(scene, mesh, B);
  if (!out) throw InputError({path}, "error while writing the radiosity file");
}

void writeImage(const SolveArguments& a, const Scene& scene, const Mesh& mesh, const RgbField& B,
                const RgbField& corners = {}) {
#ifdef RT_HAVE_VIZ
  viz::ImageOptions image;
  image.width = a.width;
  image.height = a.height;
  image.exposure = a.exposure;
  image.toneMap = viz::toneMapFromName(a.toneMap);
  image.smooth = a.smooth;
  image.showEdges = a.edges;
  viz::renderRadiosityImage(mesh, B, corners, scene.cameraOrDefault(), image, a.image);
  std::cerr << "image written to " << a.image << "\n";
#else
  throw std::runtime_error("--image needs the visualisation library (configure with RT_BUILD_VIZ=ON)");
#endif
}

// The solved mesh for ParaView and Blender. A linear basis's vertices carry its solution at the element
// corners, the node values themselves; a constant basis's carry the values the viewer's smooth display
// computes when the visualisation library is built, each element's own value at its corners otherwise.
void writePly(const Mesh& mesh, const RgbField& B, const std::string& path, const RgbField& corners = {}) {
  if (corners.rows() > 0) {
    writeRadiosityPly(mesh, B, corners, path);
    std::cerr << "mesh with the linear basis's node values written to " << path << "\n";
    return;
  }
#ifdef RT_HAVE_VIZ
  writeRadiosityPly(mesh, B, viz::smoothCornerValues(mesh, B).values, path);
#else
  writeRadiosityPly(mesh, B, flatCorners(mesh, B), path);
#endif
  std::cerr << "mesh with radiosity written to " << path << "\n";
}

// --mesh adaptive|discontinuity|hierarchical: the refining solvers build their own mesh and form factors.
void runRefined(const SolveArguments& a, const Scene& scene) {
  RefineOptions options = a.refine;
  options.mode = refineModeFromString(a.refineMode);
  options.solverTolerance = a.s.tolerance;
  ProgressLine progress(true);
  const RefinedSolution solution = solveRefined(scene, options, progress);
  progress.finish();
  std::cerr << "mesh (" << a.refineMode << "): " << solution.stats.summary() << "\n";
  if (!a.output.empty()) {
    writeRadiosityCsv(scene, solution.mesh, solution.B, a.output);
    std::cerr << "radiosity written to " << a.output << "\n";
  }
  if (!a.ply.empty()) writePly(solution.mesh, solution.B, a.ply);
  if (!a.image.empty()) writeImage(a, scene, solution.mesh, solution.B);
}

// The outputs of both ways of solving.
// `corners`, `nodal`: a linear basis's values at the element corners and at its nodes (empty for a constant
// basis): the image and the PLY's vertices hold them as they are, --nodes writes the nodes; the CSV holds
// the element averages.
void writeOutputs(const SolveArguments& a, const Scene& scene, const Mesh& mesh, const RgbField& B,
                  const RgbField& corners = {}, const RgbField& nodal = {}) {
  if (!a.ply.empty()) writePly(mesh, B, a.ply, corners);
  if (!a.nodes.empty()) {
    std::ofstream out(a.nodes);
    if (!out) throw InputError({a.nodes}, "cannot write the node values");
    out << nodalCsv(scene, mesh, buildLinearBasis(mesh), nodal);
    if (!out) throw InputError({a.nodes}, "error while writing the node values");
    std::cerr << "node values written to " << a.nodes << "\n";
  }
  if (!a.output.empty()) {
    writeRadiosityCsv(scene, mesh, B, a.output);
    std::cerr << "radiosity written to " << a.output << "\n";
  }
  if (!a.image.empty()) writeImage(a, scene, mesh, B, corners);
}

// --no-matrix: the shooting solvers ask for the shooter's row of F when it shoots; nothing n x n is stored.
const char* noMatrixProblem(const std::string& solverName, const std::string& formFactors) {
  if (solverName != "southwell" && solverName != "progressive")
    return "--no-matrix needs a shooting solver: --solver southwell or --solver progressive";
  const auto methods = rowProviderMethods();
  if (std::find(methods.begin(), methods.end(), formFactors) == methods.end())
    return "--no-matrix computes rows at the shooter: --method hemicube or --method raycast";
  return nullptr;
}

// Status check of the rows-on-demand solve (the pipeline's solve checks its own).
void checkStatus(const SolveArguments& a, SolverStatus status, double error, int iterations) {
  if (status == SolverStatus::NoConvergence)
    std::cerr << "warning: not converged: the iteration cap ("
              << (a.s.maxIterations > 0 ? "--iterations " + std::to_string(a.s.maxIterations)
                                        : std::to_string(iterations) + ", automatic; --iterations raises it")
              << ") was reached with relative residual " << error << "\n";
  if (status != SolverStatus::Success && status != SolverStatus::NoConvergence)
    throw std::runtime_error("the solver failed: " + toString(status));
}

void run(const SolveArguments& a) {
  checkOutputPaths({a.output, a.image, a.ply, a.nodes});  // before the expensive part, not after it
  if (!a.nodes.empty() && a.s.basis != "linear")
    throw CLI::ValidationError("--nodes", "node values are a linear basis's: add --basis linear");
  Scene scene = loadSceneReportingWarnings(a.scene);
  a.camera.applyTo(scene);
  requireLight(scene);
  if (!a.refineMode.empty()) {
    if (a.s.basis != "constant") throw CLI::ValidationError("--basis", "--mesh refines a constant basis");
    return runRefined(a, scene);
  }
  const std::string solverName = !a.s.solver.empty() ? a.s.solver
                                 : a.noMatrix        ? std::string("southwell")
                                                     : std::string();
  const std::string formFactors = a.noMatrix && !a.formFactorsGiven ? std::string("hemicube") : a.s.method;
  if (!solverName.empty()) makeSolver(solverName);  // an unknown name fails before the expensive part
  if (a.noMatrix && a.s.basis != "constant")
    throw CLI::ValidationError("--basis", "--no-matrix shoots rows of F: a constant basis only");
  if (a.noMatrix)
    if (const char* problem = noMatrixProblem(solverName, formFactors)) throw CLI::ValidationError(problem);
  const Mesh mesh = buildMesh(scene, a.s.mesh.optionsFor(scene));
  if (a.noMatrix) {
    ProgressLine progress(!a.s.verbose);
    const std::string name = solverName.empty() ? chooseSolver(mesh.size()) : solverName;
    RadiositySystem system;
    system.reflectance = mesh.reflectance;
    system.emission = mesh.emission;
    system.areas = mesh.areas();
    std::cerr << "form factors (" << formFactors << "): one row per shot, no matrix stored\n";
    auto solver = makeSolver(name);
    solver->setOptions(a.s.solverOptions());
    solver->setProgress(&progress);
    if (a.s.verbose) solver->setObserver(printIteration);
    std::size_t rows = 0;
    const FormFactorRowProvider provider = makeRowProvider(formFactors, mesh, a.s.formFactorOptions());
    dynamic_cast<ShootingSolver&>(*solver).setRowProvider([&rows, provider](int i, std::span<double> row) {
      ++rows;
      provider(i, row);
    });
    const RgbField B = solver->compute(system).solve();
    progress.finish();
    std::cerr << "solve (" << name << ", rows on demand): " << toString(solver->info()) << " after "
              << solver->iterations() << " shots, " << rows << " rows computed, unshot residual "
              << solver->error() << "\n";
    checkStatus(a, solver->info(), solver->error(), solver->iterations());
    writeOutputs(a, scene, mesh, B);
    return;
  }
  // The pipeline's form factors and solve, as the lessons, the app and the commands built on a solution
  // compute them.
  Pipeline pipeline;
  SolutionArguments settings = a.s;
  settings.method = formFactors;
  settings.solver = solverName;
  settings.automatic = solverName.empty() && !a.formFactorsGiven;
  const SolveOutcome outcome = solveMesh(mesh, settings, pipeline);
  writeOutputs(a, scene, mesh, outcome.B, outcome.corners, outcome.nodal);
}

}  // namespace

void addSolveCommand(CLI::App& app) {
  auto a = std::make_shared<SolveArguments>();
  a->s.method = defaultFormFactorMethod();
  auto* command =
      app.add_subcommand("solve", "Solve the radiosity system of a scene; write B.csv and/or an image");
  command->add_option("scene", a->scene, "Scene file (.json or .obj)")->required()->check(CLI::ExistingFile);
  // The settings every solving command shares (method, solver, tolerances, seeds, knobs, mesh, --verbose),
  // then what solve adds to them.
  a->s.add(*command);
  command->get_option("--solver")
      ->default_str(
          "by size: direct below 3,000 elements, local-lines above (gauss-seidel when --method is given)");
  auto* formFactors = command->get_option("--method");
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
  addDeprecatedAlias(*command, "--max-iterations", command->get_option("--iterations"));
  command->add_flag("--ambient", a->s.ambient, "progressive: show B plus the ambient term");
  command->add_flag("--no-matrix", a->noMatrix,
                    "southwell/progressive: compute each shooter's row of F when it shoots (--formfactors "
                    "hemicube, the default here, or raycast) instead of storing the n x n matrix");
  a->camera.add(*command);
  command->add_option("--output", a->output,
                      "Write B per element as CSV (element,patch,surface,area,B_r,B_g,B_b,x,y,z,nx,ny,nz: "
                      "the centroid and the unit normal)");
  command->add_option(
      "--ply", a->ply,
      "Write the solved mesh as PLY (ParaView, Blender): B per face and per vertex (smooth; with --basis "
      "linear, the linear function's node values), with display colours");
  command->add_option("--nodes", a->nodes,
                      "--basis linear: write B per node as CSV (node,patch,surface,weight,B_r,B_g,B_b,x,y,z,"
                      "nx,ny,nz: the node's share of area, its position and its patch's unit normal)");
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
  command->callback([a, formFactors] {
    a->formFactorsGiven = formFactors->count() > 0;
    // `solve --method` used to name the solver: a solver's name there still works, with a note.
    const auto& methods = lesson::knownMethods();
    if (!isSolverName(a->s.method) && std::find(methods.begin(), methods.end(), a->s.method) == methods.end())
      throw CLI::ValidationError("--method", "unknown form-factor method '" + a->s.method + "'");
    if (isSolverName(a->s.method)) {
      std::cerr << "radiosity: --method names the form-factor method now; use --solver " << a->s.method
                << "\n";
      a->s.solver = a->s.method;
      a->s.method = defaultFormFactorMethod();
      a->formFactorsGiven = false;
    }
    if (!a->legacyFormFactors.empty()) {
      a->s.method = a->legacyFormFactors;
      a->formFactorsGiven = true;
    }
    run(*a);
  });
}

}  // namespace rt::cli
