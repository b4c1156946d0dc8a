// Plain Monte Carlo, the constant control variate and quasi-Monte Carlo lines side by side (Dutré, Bekaert
// and Bala 2006, sec. 6.6): a line-tracing solver is run at several ray budgets and several seeds with each
// variant, and its error against a reference solution is fitted against the rays on a log-log scale (plain
// Monte Carlo: rays^-1/2). The control variate's row sums are counted apart, as a fixed cost that does not
// grow with the budget (counted in, they would weigh most at small budgets and bend the slope).
// `radiosity bench sampling` prints it (docs/benchmarks.md) and the lessons'
// sampling stage draws it.
#pragma once

#include <string>
#include <vector>

#include "core/progress.h"
#include "core/solvers/solver.h"

namespace rt {

struct SamplingVariant {
  std::string name;  // "monte-carlo", "control-variate", "quasi-monte-carlo"
  LineSampling sampling = LineSampling::Random;
  bool controlVariate = false;
};
const std::vector<SamplingVariant>& samplingVariants();

struct SamplingPoint {
  long raysPerIteration = 0;
  double rays = 0;           // mean over the seeds of the rays the iterations shot
  double rowSumRays = 0;     // the control variate's row sums: a fixed cost, paid once, not in `rays`
  double seconds = 0;        // mean run time
  double error = 0;          // root mean square over the seeds of the area-weighted relative RMS error
  double standardError = 0;  // mean over the seeds of the solver's own estimate, in the same measure
};

struct SamplingSeries {
  SamplingVariant variant;
  std::vector<SamplingPoint> points;
  double slope = 0;  // log-log slope of error against rays
};

struct SamplingStudyOptions {
  std::string solver = "local-lines";  // a solver that takes `sampling` and `control-variate`
  std::vector<long> raysPerIteration;
  int seeds = 4;  // runs per point: seeds base.seed, base.seed + 1, ...
  SolverOptions base;
};

// system.mesh is required; reference is the solution the errors are measured against (a direct solve of a
// well-computed F). Throws std::invalid_argument for a solver that does not take the two options, for an
// empty ray list or for a reference of the wrong size; returns what it has when progress is cancelled.
std::vector<SamplingSeries> runSamplingStudy(const RadiositySystem& system, const RgbField& reference,
                                             const SamplingStudyOptions& options,
                                             Progress* progress = nullptr);

// The comparison at equal cost: `variant`'s error at its largest budget over plain Monte Carlo's error at
// the same rays, the row sums' included, read off plain Monte Carlo's fitted power law through its largest
// point. Below 1 when the variant wins at equal rays; 0 when either series is empty or plain has no rays.
double errorRatioAtEqualRays(const SamplingSeries& plain, const SamplingSeries& variant);

}  // namespace rt
