#include "core/solvers/sampling_study.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/power_law.h"
#include "core/solvers/line_shooting.h"
#include "core/solvers/solver_support.h"

namespace rt {

const std::vector<SamplingVariant>& samplingVariants() {
  static const std::vector<SamplingVariant> variants{
      {"monte-carlo", LineSampling::Random, false},
      {"control-variate", LineSampling::Random, true},
      {"quasi-monte-carlo", LineSampling::Sobol, false},
  };
  return variants;
}

std::vector<SamplingSeries> runSamplingStudy(const RadiositySystem& system, const RgbField& reference,
                                             const SamplingStudyOptions& options, Progress* progress) {
  const std::vector<std::string>& settings = solverInfo(options.solver).settings;
  for (const char* key : {"sampling", "control-variate"})
    if (std::find(settings.begin(), settings.end(), key) == settings.end())
      throw std::invalid_argument("solver '" + options.solver + "' has no option '" + key + "'");
  if (options.raysPerIteration.empty()) throw std::invalid_argument("no ray budgets to measure");
  if (reference.rows() != static_cast<Eigen::Index>(system.size()))
    throw std::invalid_argument("the reference has " + std::to_string(reference.rows()) +
                                " elements, the system " + std::to_string(system.size()));
  const int seeds = std::max(1, options.seeds);
  const auto& variants = samplingVariants();
  const double runs = double(variants.size() * options.raysPerIteration.size()) * seeds;
  double done = 0;
  std::vector<SamplingSeries> out;
  for (const SamplingVariant& variant : variants) {
    SamplingSeries series{variant, {}, 0};
    std::vector<double> rays, errors;
    for (const long budget : options.raysPerIteration) {
      SamplingPoint point;
      point.raysPerIteration = budget;
      double squares = 0;
      for (int s = 0; s < seeds; ++s) {
        if (progress && progress->cancelled()) return out;
        SolverOptions o = options.base;
        o.raysPerIteration = budget;
        o.seed = options.base.seed + static_cast<std::uint64_t>(s);
        o.sampling = variant.sampling;
        o.controlVariate = variant.controlVariate;
        o.recordHistory = false;
        auto solver = makeSolver(options.solver);
        solver->setOptions(o);
        long used = 0;
        double seconds = 0;
        solver->setObserver([&](const IterationRecord& r) {
          used = r.rays;
          seconds = r.seconds;
        });
        const RgbField B = solver->compute(system).solve();
        const double error = solver_detail::relativeAreaRms(B - reference, reference, system.areas);
        squares += error * error;
        // The row sums are estimated once, the first time a nonzero beta needs them (local_lines_solver.h).
        const double rowSums = variant.controlVariate && used > long(kRowSumLines * system.size())
                                   ? double(kRowSumLines) * double(system.size())
                                   : 0.0;
        point.rays += (double(used) - rowSums) / seeds;
        point.rowSumRays += rowSums / seeds;
        point.seconds += seconds / seeds;
        point.standardError +=
            solver_detail::relativeAreaRms(solver->standardError(), B, system.areas) / seeds;
        if (progress) progress->report(++done / runs, variant.name);
      }
      point.error = std::sqrt(squares / seeds);
      rays.push_back(point.rays);
      errors.push_back(point.error);
      series.points.push_back(point);
    }
    series.slope = logLogSlope(rays, errors);
    out.push_back(series);
  }
  return out;
}

double errorRatioAtEqualRays(const SamplingSeries& plain, const SamplingSeries& variant) {
  if (plain.points.empty() || variant.points.empty()) return 0.0;
  const SamplingPoint& mc = plain.points.back();
  const SamplingPoint& last = variant.points.back();
  if (mc.rays <= 0) return 0.0;
  const double mcHere = mc.error * std::pow((last.rays + last.rowSumRays) / mc.rays, plain.slope);
  return mcHere > 0 ? last.error / mcHere : 0.0;
}

}  // namespace rt
