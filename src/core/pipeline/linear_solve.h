// The pipeline's path for the linear basis (basis/linear_basis.h): the nodes' kernel K in place of F, the
// nodes' system solved by any solver that reads a matrix, and the answer handed on both as the linear
// function (per node and per element corner, drawn as it is) and as element averages (what every view of
// a constant basis reads).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "core/basis/linear_basis.h"
#include "core/pipeline/pipeline.h"

namespace rt {

struct LinearKernel {
  LinearBasis basis;
  FormFactorMatrix K;  // m x m, the nodes' kernel integrals
  FormFactorStats stats;
};

// The basis and its kernel for a mesh. Throws InputError for a mesh the basis cannot use, Cancelled.
std::shared_ptr<const LinearKernel> computeLinearKernel(const Mesh& mesh, const FormFactorOptions& options,
                                                        Progress& progress);

// b = E + rho K b over the nodes: weights as areas, no mesh (nothing traces rays through nodes).
RadiositySystem linearSystem(const LinearKernel& kernel);

// Whether `solver` solves the nodes' system: those that read a matrix and use it as the equations say
// (direct, jacobi, gauss-seidel, southwell, progressive, bounces). The stochastic ones that draw a row's
// entries as the chances of power moving from i to j rely on reciprocity, A_i F_ij = A_j F_ji, which a
// collocation kernel lacks; those that trace rays solve for one value per element.
bool linearBasisSolves(const std::string& solver);
// Why `solver` (empty: chosen by size) or `method` cannot be used with the linear basis; empty when they
// can. The kernel is integrated by quadrature, whatever other method is named.
std::string linearBasisProblem(const std::string& solver, const std::string& method);

// Solves the nodes' system (solveRadiosity) and returns B as element averages, with the linear function
// itself in `nodal` and `corners`; a recorded history holds element averages too.
SolveOutcome solveLinearBasis(const LinearKernel& kernel, const std::string& solver, SolverOptions options,
                              bool recordHistory, Progress& progress,
                              const std::function<void(const IterationRecord&)>& observer = {});

}  // namespace rt
