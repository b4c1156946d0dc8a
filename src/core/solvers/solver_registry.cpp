#include <cstdio>
#include <stdexcept>

#include "core/solvers/bounces_solver.h"
#include "core/solvers/clustering_solver.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/gathering_solvers.h"
#include "core/solvers/local_lines_solver.h"
#include "core/solvers/random_walks.h"
#include "core/solvers/shooting_solvers.h"
#include "core/solvers/solver.h"
#include "core/solvers/stochastic_solvers.h"

namespace rt {

const std::vector<SolverInfo>& solverTable() {
  using enum SolverInput;
  static const std::vector<SolverInfo> table{
      {"direct", Matrix, "LU of K = I - rho F, exact to rounding; O(n^3)", {}},
      {"jacobi", Matrix, "every element gathers from the previous sweep", {"tolerance", "iterations"}},
      {"gauss-seidel",
       Matrix,
       "every element gathers, using this sweep's values at once (SOR with relaxation)",
       {"tolerance", "iterations", "relaxation"}},
      {"southwell",
       MatrixOrRows,
       "the element with most unshot power shoots it",
       {"tolerance", "iterations"}},
      {"progressive",
       MatrixOrRows,
       "Southwell shooting, optionally showing the unshot light as an ambient term",
       {"tolerance", "iterations", "ambient"}},
      {"bounces", Matrix, "one more bounce of the Neumann series per iteration", {"tolerance", "iterations"}},
      {"stochastic-jacobi",
       Matrix,
       "incremental stochastic Jacobi drawing its lines from the rows of a stored F",
       {"tolerance", "iterations", "seed", "rays-per-iteration"}},
      {"random-walk",
       Matrix,
       "random walks from the emitters, jumping by the rows of F; every collision scores (collision "
       "estimator)",
       {"tolerance", "iterations", "seed", "rays-per-iteration"}},
      {"random-walk-absorption",
       Matrix,
       "the same random walks, scoring only where each walk is absorbed (absorption estimator)",
       {"tolerance", "iterations", "seed", "rays-per-iteration"}},
      {"local-lines",
       Geometry,
       "incremental stochastic Jacobi: shoots the unshot power with rays traced through the scene; stores no "
       "form factor, memory O(n)",
       {"tolerance", "iterations", "seed", "rays-per-iteration", "sampling", "control-variate"}},
      {"local-lines-regular",
       Geometry,
       "regular stochastic Jacobi: every iteration shoots all the power again with rays traced through the "
       "scene and the iterates after a burn-in are averaged; stores no form factor",
       {"tolerance", "iterations", "seed", "rays-per-iteration", "sampling", "control-variate"}},
      {"photon-density",
       Geometry,
       "continuous random walks: photon trajectories traced through the scene from the lights, their hit "
       "points histogrammed per element (the photon density is the irradiance); stores no form factor",
       {"tolerance", "iterations", "seed", "rays-per-iteration"}},
      {"hierarchical-clustering",
       Geometry,
       "gathers along links between clusters of elements, refined by a bound on what each link carries; "
       "stores no form factor matrix, memory about O(n)",
       {"tolerance", "iterations", "seed", "cluster-tolerance"}},
  };
  return table;
}

const SolverInfo& solverInfo(const std::string& name) {
  for (const SolverInfo& info : solverTable())
    if (info.name == name) return info;
  std::string known;
  for (const std::string& n : solverNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown solver '" + name + "' (known: " + known + ")");
}

bool solverNeedsMatrix(const std::string& name) {
  return solverInfo(name).input != SolverInput::Geometry;
}

std::unique_ptr<Solver> makeSolver(const std::string& name) {
  using solver_detail::AlgorithmSolver;
  solverInfo(name);  // an unknown name throws, naming the known ones
  if (name == "direct") return std::make_unique<AlgorithmSolver>(name, &directSolve);
  if (name == "jacobi") return std::make_unique<AlgorithmSolver>(name, &jacobi);
  if (name == "gauss-seidel") return std::make_unique<AlgorithmSolver>(name, &gaussSeidel);
  if (name == "southwell") return std::make_unique<ShootingSolver>(false);
  if (name == "progressive") return std::make_unique<ShootingSolver>(true);
  if (name == "bounces") return std::make_unique<BouncesSolver>();
  if (name == "stochastic-jacobi") return std::make_unique<StochasticSolver>(name, &stochasticJacobi);
  if (name == "random-walk") return std::make_unique<StochasticSolver>(name, &randomWalk);
  if (name == "random-walk-absorption")
    return std::make_unique<StochasticSolver>(name, &randomWalkAbsorption);
  if (name == "local-lines") return std::make_unique<StochasticSolver>(name, &localLines);
  if (name == "local-lines-regular") return std::make_unique<StochasticSolver>(name, &regularLocalLines);
  if (name == "photon-density") return std::make_unique<StochasticSolver>(name, &photonDensity);
  if (name == "hierarchical-clustering")
    return std::make_unique<StochasticSolver>(name, &hierarchicalClustering);
  throw std::logic_error("solver '" + name + "' is in the table but has no implementation");
}

std::vector<std::string> solverNames() {
  std::vector<std::string> names;
  for (const SolverInfo& info : solverTable()) names.push_back(info.name);
  return names;
}

// LU costs O(n^3) but is exact and, up to a few thousand elements, faster than waiting for an iteration to
// converge; beyond that O(n^2) sweeps win and the n x n factorisation would not fit comfortably in memory.
std::string chooseSolver(std::size_t n) {
  return n <= 3000 ? "direct" : "gauss-seidel";
}

// Measured on the 2-core machine (docs/benchmarks.md): the default form factors with a direct solve take 1 s
// at 850 elements and grow like n^2 (82 s at 6,000) with n^2 memory (16k elements: 2 GB); local lines reach
// 0.5 % relative standard error in 0.3 s at 2,400 elements and 23 s at 49,000, in memory that grows like n.
// Below the crossing the exact solve of well-sampled form factors is both fast and free of noise.
AutomaticSolve chooseAutomaticSolve(std::size_t n) {
  constexpr std::size_t kLocalLinesFrom = 3000;
  const std::string count = std::to_string(n) + " elements";
  if (n < kLocalLinesFrom)
    return {chooseSolver(n), true,
            count + ": form factors stored and solved exactly (below " + std::to_string(kLocalLinesFrom) +
                " elements this takes seconds)"};
  const double gigabytes = 8.0 * static_cast<double>(n) * static_cast<double>(n) / 1e9;
  char size[32];
  std::snprintf(size, sizeof size, "%.2g", gigabytes);
  return {"local-lines", false,
          count + ": a stored F would take " + size +
              " GB and time growing like n^2; local lines trace rays through the mesh instead (memory like "
              "n) and stop at a relative standard error of about 0.5 %, printed at the end"};
}

}  // namespace rt
