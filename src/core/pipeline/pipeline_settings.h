// What one run of the pipeline (scene -> mesh -> form factors -> solve) depends on. The lessons, the app, the
// CLI and the benchmarks all describe a computation with this struct; a lesson step's parameters map to it in
// one place (lesson/step_settings.h).
#pragma once

#include <map>
#include <string>

#include "core/basis/linear_basis.h"
#include "core/formfactor/formfactor_method.h"
#include "core/mesh.h"
#include "core/solvers/solver.h"

namespace rt {

struct PipelineSettings {
  MeshOptions mesh;
  // Constant: one unknown per element, F. Linear: one per node, the collocation kernel of
  // basis/linear_kernel.h (the method must be the default, whose quadrature integrates it; the solver must
  // read a matrix).
  Basis basis = Basis::Constant;
  std::string method = defaultFormFactorMethod();
  FormFactorOptions formFactors;
  std::string solver;  // empty: chooseSolver(n)
  SolverOptions solverOptions;
  std::map<std::string, Rgb> reflectance;  // surface name -> reflectance override
  double lightScale = 1.0;                 // multiplies every emission
  bool recordHistory = false;              // keep every iteration's B (the app replays them)
};

}  // namespace rt
