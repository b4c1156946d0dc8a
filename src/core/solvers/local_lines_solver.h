// Stochastic Jacobi with local lines traced through the geometry (Dutré, Bekaert and Bala, "Advanced Global
// Illumination", 2nd ed., 2006, sec. 6.3; Bekaert, "Hierarchical and stochastic algorithms for radiosity",
// 1999, ch. 5; Sbert 1993). A line's landing element comes from a ray cast into the scene (line_shooting.h),
// never from a row of F: no form factor is computed or stored, memory is O(n) (the mesh, its Embree scene and
// a few n x 3 fields), and the cost of an iteration is its rays times the cost of a ray, about log n.
//
// local-lines, incremental stochastic Jacobi: one iteration shoots all unshot power, the source of each ray
// drawn proportional to its unshot power (so every ray carries the same total power), and rho times what an
// element receives is its unshot power for the next iteration; B is E plus everything received. A line that
// escapes, or that hits the back of a polygon (one-sided: it neither reflects nor passes), is lost, as a row
// of F summing to less than 1 loses it. The ray budget of an iteration is options.raysPerIteration times the
// fraction of the emitted power still unshot (0 = localLinesDefaultRays); it stops when the unshot power is
// <= options.tolerance times the emitted power. The recorded residual is ||unshot|| / ||E|| (the residual of
// B - unshot), the exact one needing F.
//
// local-lines-regular, regular stochastic Jacobi: iteration k shoots the whole power of the previous iterate,
// B^(k) = E + rho * (what B^(k-1) sends, estimated by options.raysPerIteration lines, 0 =
// localLinesDefaultRays). The iterates do not converge: once the start B^(0) = E has died out they fluctuate
// about the solution with the noise of one iteration's lines. The start's share of B^(k) is at most
// rho_max^k, so the first regularBurnIn(rho_max, tolerance) iterates are only a burn-in; the result is the
// mean of the iterates after it, whose noise falls like 1 / sqrt(the iterates averaged). It stops when that
// mean's relative standard error is <= options.tolerance. The recorded residual is the stopping measure:
// rho_max^k during the burn-in, then the relative standard error.
//
// Both take the two variance reductions of line_shooting.h: options.sampling (Sobol lines) and
// options.controlVariate (every iteration shoots B - beta, beta = constantControl of what it shoots, and adds
// back beta A_j R_j; the row sums R_j are estimated once, with kRowSumLines lines per element, when the
// first nonzero beta needs them, and their rays are counted with the rest).
//
// Both estimate the standard error of B per element from each iteration's independent rays (the noise an
// iteration inherits from the earlier ones is not counted) and record its area-weighted RMS relative to
// that of B. Both are deterministic for options.seed at any thread count.
#pragma once

#include <cstddef>

#include "core/solvers/solver.h"

namespace rt {

// system.mesh is required (InvalidInput without it); system.F is never read. standardError (optional):
// per-element standard error of B (n x 3).
SolverStatus localLines(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                        const IterationSink& sink = {}, RgbField* standardError = nullptr);
SolverStatus regularLocalLines(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                               const IterationSink& sink = {}, RgbField* standardError = nullptr);

// The rays of the first iteration when options.raysPerIteration is 0: 1000 per element (about 3 % noise per
// element after all iterations), at least 100,000.
long localLinesDefaultRays(std::size_t elements);

// The iterations local-lines-regular discards: the smallest k with rhoMax^k <= tolerance (0 when rhoMax is
// 0; never ending when rhoMax >= 1).
int regularBurnIn(double rhoMax, double tolerance);

}  // namespace rt
