// Stochastic Jacobi with local lines traced through the geometry (Bekaert, "Hierarchical and stochastic
// algorithms for radiosity", 1999, ch. 5; Sbert 1993): the same incremental shooting as stochastic-jacobi,
// but a line's landing element comes from a ray cast into the scene instead of a row of a stored F. No form
// factor is ever computed or stored: memory is O(n) (the mesh, its Embree scene and a few n x 3 fields), and
// the cost of an iteration is its rays times the cost of a ray, about log n.
//
// One iteration shoots all unshot power: each ray's source element is drawn proportional to its unshot power
// (summed over the channels, so every ray carries the same total power and the source's colour), its origin
// uniformly on the element and its direction cosine-distributed about the element's normal; the first element
// hit receives the ray's power, and rho times what an element receives is its unshot power for the next
// iteration. A ray that escapes, or that hits the back of a polygon (one-sided: it neither reflects nor
// passes), is lost, as a row of F summing to less than 1 loses it. The ray budget of an iteration is
// options.raysPerIteration times the fraction of the emitted power still unshot (0 = 1000 rays per element,
// at least 100,000); it stops when the unshot power is <= options.tolerance times the emitted power.
//
// The standard error of B is estimated per element from each iteration's independent rays, as
// stochastic-jacobi does, and recorded as its area-weighted RMS relative to that of B; the recorded residual
// is ||unshot|| / ||E|| (the residual of B - unshot), the exact one needing F.
//
// Deterministic for options.seed at any thread count: rays are cut into fixed chunks, each with its own
// random stream seeded from (seed, iteration, chunk), and the scores are added in 2^-32 fixed point, whose
// integer sums do not depend on the order the threads add them in.
#pragma once

#include <cstddef>

#include "core/solvers/solver.h"

namespace rt {

// system.mesh is required (InvalidInput without it); system.F is never read. standardError (optional):
// per-element standard error of B (n x 3).
SolverStatus localLines(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                        const IterationSink& sink = {}, RgbField* standardError = nullptr);

// The rays of the first iteration when options.raysPerIteration is 0: 1000 per element (about 3 % noise per
// element after all iterations), at least 100,000.
long localLinesDefaultRays(std::size_t elements);

}  // namespace rt
