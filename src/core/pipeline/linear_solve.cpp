#include "core/pipeline/linear_solve.h"

#include <chrono>

#include "core/basis/linear_kernel.h"

namespace rt {

std::shared_ptr<const LinearKernel> computeLinearKernel(const Mesh& mesh, const FormFactorOptions& options,
                                                        Progress& progress) {
  auto kernel = std::make_shared<LinearKernel>();
  kernel->basis = buildLinearBasis(mesh);
  const auto start = std::chrono::steady_clock::now();
  kernel->K = linearKernelMatrix(mesh, kernel->basis, options, progress, kernel->stats);
  kernel->stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return kernel;
}

RadiositySystem linearSystem(const LinearKernel& kernel) {
  RadiositySystem s;
  s.F = &kernel.K;
  s.reflectance = kernel.basis.reflectance;
  s.emission = kernel.basis.emission;
  s.areas = kernel.basis.weights;
  return s;
}

bool linearBasisSolves(const std::string& solver) {
  for (const char* name : {"direct", "jacobi", "gauss-seidel", "southwell", "progressive", "bounces"})
    if (solver == name) return true;
  return false;
}

std::string linearBasisProblem(const std::string& solver, const std::string& method) {
  if (!method.empty() && method != defaultFormFactorMethod())
    return "the linear basis integrates its own kernel by quadrature (Lambert's formula weighted by the "
           "shape functions): method '" +
           method + "' does not apply; leave the method out or name " + defaultFormFactorMethod();
  if (!solver.empty() && !solverNeedsMatrix(solver))
    return "solver '" + solver +
           "' traces rays through the elements and solves for one value per element: the linear basis "
           "needs direct, jacobi, gauss-seidel, southwell, progressive or bounces";
  if (!solver.empty() && !linearBasisSolves(solver))
    return "solver '" + solver +
           "' draws the entries of a row as the chances that power moves, which needs reciprocity (A_i F_ij "
           "= A_j F_ji); the linear basis's collocation kernel has none: use direct, jacobi, gauss-seidel, "
           "southwell, progressive or bounces";
  return {};
}

SolveOutcome solveLinearBasis(const LinearKernel& kernel, const std::string& solver, SolverOptions options,
                              bool recordHistory, Progress& progress,
                              const std::function<void(const IterationRecord&)>& observer) {
  const RadiositySystem system = linearSystem(kernel);
  // chooseSolver by the node count: the automatic choice may trace rays, which nodes cannot.
  const std::string name = !solver.empty()                                  ? solver
                           : solverNeedsMatrix(chooseSolver(system.size())) ? chooseSolver(system.size())
                                                                            : std::string("gauss-seidel");
  SolveOutcome out = solveRadiosity(system, name, options, recordHistory, progress, observer);
  out.nodal = out.B;
  out.corners = kernel.basis.cornerValues(out.nodal);
  out.B = kernel.basis.elementAverages(out.nodal);
  if (out.standardErrors.rows() > 0) out.standardErrors = kernel.basis.elementAverages(out.standardErrors);
  for (IterationRecord& record : out.history) {
    record.B = kernel.basis.elementAverages(record.B);
    if (record.unshot.rows() > 0) record.unshot = kernel.basis.elementAverages(record.unshot);
  }
  return out;
}

}  // namespace rt
