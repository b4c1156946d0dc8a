#include <stdexcept>

#include "core/solvers/solver.h"

namespace rt {

std::unique_ptr<Solver> makeSolver(const std::string& name) {
  throw std::invalid_argument("unknown solver '" + name + "'");
}

std::vector<std::string> solverNames() { return {}; }

}  // namespace rt
