// The radiosity solution as `radiosity solve` computes it on a uniform mesh: the settings it reads, how they
// become form-factor and solver options, and the pipeline's form factors and solve with the same reports on
// stderr. The commands that build on a solution (the point query, the comparison with the path tracer) get
// theirs here, so that they see the very numbers `solve` writes.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "cli/cli_common.h"
#include "core/pipeline/pipeline.h"

namespace rt::cli {

struct SolutionArguments {
  std::string solver;  // empty: chosen by size
  std::string method;  // form-factor method; empty: the table's default (one that handles occluders)
  std::string basis = "constant";  // constant or linear (core/basis/linear_basis.h)
  double tolerance = 1e-6;
  int maxIterations = 0;  // automatic
  std::uint64_t seed = 1;
  int raysPerIteration = 0;         // stochastic solvers; 0 = automatic
  std::string sampling = "random";  // montecarlo method, local-lines solvers
  bool controlVariate = false;      // local-lines solvers
  double clusterTolerance = 0;      // hierarchical-clustering; 0 = automatic
  int resolution = 128;
  int samples = 16;
  double formFactorTolerance = 0;  // the method's own
  bool ambient = false;
  bool verbose = false;
  // Neither a solver nor a form-factor method was named: choose both by the mesh's size and say why
  // (chooseAutomaticSolve). Otherwise an unnamed solver is chooseSolver's.
  bool automatic = false;
  MeshArguments mesh;

  // --method, --solver, --tolerance, --iterations, --seed, --resolution, --samples, the mesh options and
  // --verbose, spelled and checked as the step-key table says (solve adds its older spellings itself).
  void add(CLI::App& command);
  FormFactorOptions formFactorOptions() const;
  SolverOptions solverOptions() const;
};

struct Solution {
  Mesh mesh;
  SolveOutcome outcome;
  std::shared_ptr<const CachedFormFactors> formFactors;  // the F it was solved with; null for a solver
                                                         // that traces its own rays (local-lines)
};

// Meshes the scene (the default mesh when no mesh option is given), computes F through `pipeline` (none for
// a solver that does not read it) and solves, reporting as `solve` does. Throws std::runtime_error when the
// solver fails outright; a solve that stops at its iteration cap is returned with a warning on stderr.
Solution solveOnMesh(const Scene& scene, const SolutionArguments& arguments, Pipeline& pipeline);
// The same on a mesh of the caller's choosing.
Solution solveOnMesh(const Scene& scene, const MeshOptions& mesh, const SolutionArguments& arguments,
                     Pipeline& pipeline);
// The mesh with elements twice the size (half the splits), whose solution's difference to this one's
// estimates this one's mesh error; false when the mesh cannot be coarsened (one element per polygon).
bool coarserMesh(const MeshOptions& mesh, MeshOptions& coarser);
// The pipeline part alone, on a mesh already built; `formFactors`, when given, receives F.
SolveOutcome solveMesh(const Mesh& mesh, const SolutionArguments& arguments, Pipeline& pipeline,
                       std::shared_ptr<const CachedFormFactors>* formFactors = nullptr);

// The per-iteration line of --verbose.
void printIteration(const IterationRecord& record);

}  // namespace rt::cli
