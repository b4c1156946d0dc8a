// Gathering iterations: every element in turn collects what it sees, B_i <- E_i + rho_i sum_j F_ij B_j.
// Jacobi uses only the previous sweep's values; Gauss-Seidel uses each new value as soon as it exists, which
// for radiosity roughly halves the number of sweeps; relaxation > 1 over-relaxes Gauss-Seidel (SOR). One
// iteration = one sweep over all elements (O(n^2)). The self term F_ii (zero for planar elements) is moved to
// the left-hand side so that both are the textbook splittings of K. Elements with rho = 0 gather nothing and
// are skipped. Stops when the relative residual ||K B - E|| / ||E|| <= options.tolerance.
#pragma once

#include "core/solvers/solver.h"

namespace rt {

SolverStatus jacobi(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                    const IterationSink& sink = {});
SolverStatus gaussSeidel(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                         const IterationSink& sink = {});

}  // namespace rt
