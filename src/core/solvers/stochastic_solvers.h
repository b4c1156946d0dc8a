// Monte Carlo solvers. Both are deterministic for options.seed and report a standard error per element.
//
// No geometry is needed in core: a "local line" from element j lands on element k with probability F_jk,
// exactly what a uniformly random cosine-distributed ray leaving j would do, so the rows of F serve as
// transition probabilities (a row summing to less than 1 lets the rest escape). With geometry, a ray caster
// would draw the same events.
//
// stochastic-jacobi (Bekaert, "Hierarchical and stochastic algorithms for radiosity", 1999, ch. 5):
// incremental shooting. Each iteration shoots all unshot power with rays whose sources are drawn proportional
// to their unshot power (so every ray carries about the same power); the power a receiver collects, times
// rho, is its unshot power for the next iteration. The ray budget of an iteration is options.raysPerIteration
// times the fraction of the emitted power still unshot (0 = 100 n rays for the first iteration). Stops when
// the unshot power is <= tolerance times the emitted power: the remaining error is then noise, about
// 1/sqrt(rays), reported as the standard error.
//
// random-walk: discrete random walks (shooting; the walks themselves are random_walks.h's): a walk starts at
// an emitter drawn proportional to emitted power, jumps by F, and survives a reflection with probability
// max_c rho_c (its weight is multiplied by rho_c / that). Collision estimator: every arrival scores the
// reflected power at the element. Absorption estimator: only the arrival where the walk ends scores, weighted
// by rho / (1 - survival). One iteration = a batch of options.raysPerIteration walks (0 = 100 n). Stops when
// the relative standard error (area-weighted RMS of SE over that of B) <= tolerance.
#pragma once

#include "core/solvers/solver.h"
#include "core/solvers/solver_support.h"

namespace rt {

// standardError (optional): per-element standard error of B (n x 3).
SolverStatus stochasticJacobi(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                              const IterationSink& sink = {}, RgbField* standardError = nullptr);
SolverStatus randomWalk(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                        const IterationSink& sink = {}, RgbField* standardError = nullptr);
// randomWalk with options.walkEstimator set to Absorption, whatever it was: the registry's
// random-walk-absorption, so that the two estimators can be run side by side under one set of options.
SolverStatus randomWalkAbsorption(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                                  const IterationSink& sink = {}, RgbField* standardError = nullptr);

class StochasticSolver : public solver_detail::AlgorithmSolver {
 public:
  using Function = SolverStatus (*)(const RadiositySystem&, RgbField&, const SolverOptions&,
                                    const IterationSink&, RgbField*);
  StochasticSolver(std::string name, Function function);
  RgbField solve() override;

 private:
  Function function_;
};

}  // namespace rt
