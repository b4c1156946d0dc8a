#include "cli/solution.h"

#include <cstdio>
#include <iostream>

#include "cli/setting_options.h"
#include "core/formfactor/formfactor_method.h"
#include "core/pipeline/linear_solve.h"

namespace rt::cli {

void SolutionArguments::add(CLI::App& command) {
  if (method.empty()) method = defaultFormFactorMethod();
  addSettingOption(command, "method", method)->default_str(defaultFormFactorMethod());
  addSettingOption(command, "solver", solver)->default_str("direct for small scenes, gauss-seidel otherwise");
  addSettingOption(command, "basis", basis);
  addSettingOption(command, "tolerance", tolerance);
  addSettingOption(command, "iterations", maxIterations);
  addSettingOption(command, "seed", seed);
  addSettingOption(command, "rays-per-iteration", raysPerIteration);
  addSettingOption(command, "sampling", sampling);
  addSettingFlag(command, "control-variate", controlVariate);
  addSettingOption(command, "cluster-tolerance", clusterTolerance);
  addSettingOption(command, "resolution", resolution);
  addSettingOption(command, "samples", samples);
  addSettingOption(command, "ff-tolerance", formFactorTolerance);
  mesh.add(command);
  command.add_flag("--verbose", verbose, "One line per iteration instead of a progress line");
}

FormFactorOptions SolutionArguments::formFactorOptions() const {
  FormFactorOptions options;
  options.hemicubeResolution = resolution;
  options.samples = samples;
  options.tolerance = formFactorTolerance;
  options.seed = seed;
  options.sampling = parseLineSampling(sampling).value_or(LineSampling::Random);
  return options;
}

SolverOptions SolutionArguments::solverOptions() const {
  SolverOptions options;
  options.tolerance = tolerance;
  options.maxIterations = maxIterations;
  options.seed = seed;
  options.raysPerIteration = raysPerIteration;
  options.sampling = parseLineSampling(sampling).value_or(LineSampling::Random);
  options.controlVariate = controlVariate;
  options.clusterTolerance = clusterTolerance;
  options.ambient = ambient;
  options.recordHistory = false;
  return options;
}

void printIteration(const IterationRecord& r) {
  std::fprintf(stderr, "iteration %d: residual %.6e, unshot power %.6e%s\n", r.iteration, r.residual,
               r.unshotPower, r.shooter >= 0 ? (", shooter " + std::to_string(r.shooter)).c_str() : "");
}

namespace {

std::string solverFor(const Mesh& mesh, const SolutionArguments& a) {
  if (!a.solver.empty()) return a.solver;
  if (!a.automatic) return chooseSolver(mesh.size());
  const AutomaticSolve chosen = chooseAutomaticSolve(mesh.size());
  std::cerr << "solver: none named: " << chosen.solver << " for " << chosen.why
            << " (--solver and --method: your own)\n";
  return chosen.solver;
}

void checkOutcome(const SolveOutcome& outcome, const SolutionArguments& a) {
  if (outcome.status == SolverStatus::NoConvergence)
    std::cerr << "warning: not converged: the iteration cap ("
              << (a.maxIterations > 0
                      ? "--iterations " + std::to_string(a.maxIterations)
                      : std::to_string(outcome.iterations) + ", automatic; --iterations raises it")
              << ") was reached with relative residual " << outcome.error << "\n";
  if (outcome.status != SolverStatus::Success && outcome.status != SolverStatus::NoConvergence)
    throw std::runtime_error("the solver failed: " + toString(outcome.status));
}

std::function<void(const IterationRecord&)> observerFor(const SolutionArguments& a) {
  return a.verbose ? std::function<void(const IterationRecord&)>(printIteration)
                   : std::function<void(const IterationRecord&)>();
}

// The linear basis: the nodes' kernel in place of F, a solver that reads a matrix.
SolveOutcome solveLinear(const Mesh& mesh, const SolutionArguments& a, const std::string& method,
                         Pipeline& pipeline) {
  if (const std::string problem = linearBasisProblem(a.solver, method); !problem.empty())
    throw CLI::ValidationError("--basis", problem);
  ProgressLine progress(!a.verbose);
  const auto kernel = pipeline.linearKernel(mesh, a.formFactorOptions(), progress);
  progress.finish();
  reportFormFactorStats(std::cerr, "quadrature, linear basis", kernel->stats);
  SolveOutcome outcome =
      solveLinearBasis(*kernel, a.solver, a.solverOptions(), false, progress, observerFor(a));
  progress.finish();
  std::cerr << "solve (" << outcome.solverName << ", linear basis, " << kernel->basis.size()
            << " nodes): " << toString(outcome.status) << " after " << outcome.iterations << " "
            << (outcome.iterations == 1 ? "iteration" : "iterations") << ", relative residual "
            << outcome.residual << "\n";
  checkOutcome(outcome, a);
  return outcome;
}

}  // namespace

SolveOutcome solveMesh(const Mesh& mesh, const SolutionArguments& a, Pipeline& pipeline,
                       std::shared_ptr<const CachedFormFactors>* formFactors) {
  const std::string method = a.method.empty() ? defaultFormFactorMethod() : a.method;
  if (a.basis == "linear") return solveLinear(mesh, a, method, pipeline);
  const std::string name = solverFor(mesh, a);
  ProgressLine progress(!a.verbose);
  if (!solverNeedsMatrix(name)) {
    // It traces its own rays through the mesh: nothing n x n is computed or stored.
    std::cerr << "form factors: none (" << name << " traces rays through the " << mesh.size()
              << " elements; no matrix stored)\n";
    SolveOutcome outcome = solveRadiosity(RadiositySystem::fromGeometry(mesh), name, a.solverOptions(), false,
                                          progress, observerFor(a));
    progress.finish();
    if (outcome.links > 0)
      std::cerr << "solve (" << name << "): " << toString(outcome.status) << " after " << outcome.iterations
                << " " << (outcome.iterations == 1 ? "sweep" : "sweeps") << ", " << outcome.links
                << " links, " << outcome.nodes << " nodes, " << outcome.memoryBytes
                << " bytes of links and nodes, " << outcome.rays
                << " visibility rays, estimated relative RMS error " << outcome.standardError << "\n";
    else
      std::cerr << "solve (" << name << "): " << toString(outcome.status) << " after " << outcome.iterations
                << " " << (outcome.iterations == 1 ? "iteration" : "iterations") << ", " << outcome.rays
                << " rays, unshot residual " << outcome.error << ", relative standard error "
                << outcome.standardError << "\n";
    checkOutcome(outcome, a);
    return outcome;
  }
  const auto cached = pipeline.formFactors(mesh, method, a.formFactorOptions(), progress);
  progress.finish();
  reportFormFactorStats(std::cerr, method, cached->stats);
  if (formFactors) *formFactors = cached;
  SolveOutcome outcome = solveRadiosity(RadiositySystem::fromMesh(mesh, cached->F), name, a.solverOptions(),
                                        false, progress, observerFor(a));
  progress.finish();
  std::cerr << "solve (" << name << "): " << toString(outcome.status) << " after " << outcome.iterations
            << " " << (outcome.iterations == 1 ? "iteration" : "iterations") << ", relative residual "
            << outcome.residual << "\n";
  checkOutcome(outcome, a);
  return outcome;
}

Solution solveOnMesh(const Scene& scene, const SolutionArguments& a, Pipeline& pipeline) {
  return solveOnMesh(scene, a.mesh.optionsFor(scene), a, pipeline);
}

Solution solveOnMesh(const Scene& scene, const MeshOptions& mesh, const SolutionArguments& a,
                     Pipeline& pipeline) {
  if (!a.solver.empty()) makeSolver(a.solver);  // an unknown name fails before the expensive part
  Solution solution{buildMesh(scene, mesh), {}};
  solution.outcome = solveMesh(solution.mesh, a, pipeline, &solution.formFactors);
  return solution;
}

bool coarserMesh(const MeshOptions& mesh, MeshOptions& coarser) {
  coarser = mesh;
  if (mesh.mode == MeshOptions::Mode::MaxEdge && mesh.maxEdge > 0) {
    coarser.maxEdge = 2 * mesh.maxEdge;
    return true;
  }
  if (mesh.mode == MeshOptions::Mode::Count && mesh.count >= 2) {
    coarser.count = mesh.count / 2;
    return true;
  }
  return false;
}

}  // namespace rt::cli
