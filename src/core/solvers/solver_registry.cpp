#include <stdexcept>

#include "core/solvers/bounces_solver.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/gathering_solvers.h"
#include "core/solvers/shooting_solvers.h"
#include "core/solvers/solver.h"
#include "core/solvers/stochastic_solvers.h"

namespace rt {

std::unique_ptr<Solver> makeSolver(const std::string& name) {
  using solver_detail::AlgorithmSolver;
  if (name == "direct") return std::make_unique<AlgorithmSolver>(name, &directSolve);
  if (name == "jacobi") return std::make_unique<AlgorithmSolver>(name, &jacobi);
  if (name == "gauss-seidel") return std::make_unique<AlgorithmSolver>(name, &gaussSeidel);
  if (name == "southwell") return std::make_unique<ShootingSolver>(false);
  if (name == "progressive") return std::make_unique<ShootingSolver>(true);
  if (name == "bounces") return std::make_unique<BouncesSolver>();
  if (name == "stochastic-jacobi") return std::make_unique<StochasticSolver>(name, &stochasticJacobi);
  if (name == "random-walk") return std::make_unique<StochasticSolver>(name, &randomWalk);
  std::string known;
  for (const std::string& n : solverNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown solver '" + name + "' (known: " + known + ")");
}

std::vector<std::string> solverNames() {
  return {"direct",      "jacobi",  "gauss-seidel",      "southwell",
          "progressive", "bounces", "stochastic-jacobi", "random-walk"};
}

// LU costs O(n^3) but is exact and, up to a few thousand elements, faster than waiting for an iteration to
// converge; beyond that O(n^2) sweeps win and the n x n factorisation would not fit comfortably in memory.
std::string chooseSolver(std::size_t n) {
  return n <= 3000 ? "direct" : "gauss-seidel";
}

}  // namespace rt
