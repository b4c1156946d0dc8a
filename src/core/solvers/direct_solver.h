// The reference solution: K B = E solved by LU with partial pivoting (Eigen::PartialPivLU), one RGB channel
// at a time. O(n^3) time and O(n^2) memory; exact up to rounding, which is why every other solver is measured
// against it.
#pragma once

#include "core/solvers/solver.h"

namespace rt {

// One "iteration" is recorded (the solution). NumericalIssue (with B = E) when the LU result is not finite,
// e.g. for rho = 1 in a closed scene where K is singular.
SolverStatus directSolve(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                         const IterationSink& sink = {});

}  // namespace rt
