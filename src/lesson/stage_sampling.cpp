// The sampling stage: plain Monte Carlo lines, the constant control variate and quasi-Monte Carlo (Sobol)
// lines in one line-tracing solver, against the direct solution of F by the step's method, over the
// step's `sweep` of rays per iteration (core/solvers/sampling_study.h). Values, per variant v (monte-carlo,
// control-variate, quasi-monte-carlo): slope.v, and at sweep entry k error.v[k], rays.v[k], seconds.v[k];
// gain.v, plain Monte Carlo's error over v's at the largest sweep entry; error-ratio.v, v's error at the
// largest entry over plain Monte Carlo's at the same rays (the row sums' included), read off plain Monte
// Carlo's fitted line; seeds;
// rays-per-iteration, the largest entry; rowsum-rays, the rays of the control variate's row sums.
#include <algorithm>
#include <memory>

#include "core/solvers/direct_solver.h"
#include "core/solvers/line_shooting.h"
#include "lesson/step_settings.h"
#include "lesson/step_stages.h"

namespace rt::lesson::detail {

void computeSampling(StageContext& c) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  if (p.sweep.empty()) c.fail("sweep", "a sampling step needs `sweep`: the rays per iteration to measure");
  const auto& settings = solverInfo(p.solver).settings;
  if (std::find(settings.begin(), settings.end(), "control-variate") == settings.end())
    c.fail("solver",
           "a sampling step needs a solver that takes `sampling` and `control-variate` "
           "(local-lines or local-lines-regular), not '" +
               p.solver + "'");
  r.method = c.method();
  r.F = c.formFactors(r.mesh, r.method, "method", r.formFactorStats);
  RgbField reference;
  const SolverStatus status = directSolve(RadiositySystem::fromMesh(r.mesh, *r.F), reference, {});
  if (status != SolverStatus::Success) c.fail("method", "the direct solve of the reference failed");
  r.reference = reference;
  r.B = reference;

  SamplingStudyOptions o;
  o.solver = p.solver;
  o.seeds = 4;
  o.base = solverOptionsFor(p);
  for (const int rays : p.sweep) o.raysPerIteration.push_back(rays);
  auto series = std::make_shared<std::vector<SamplingSeries>>(
      runSamplingStudy(RadiositySystem::fromGeometry(r.mesh), reference, o, &c.progress));
  if (c.progress.cancelled() || series->size() != samplingVariants().size()) throw Cancelled();

  auto& v = r.values;
  const SamplingSeries& plain = series->front();
  for (const SamplingSeries& s : *series) {
    const std::string& name = s.variant.name;
    v["slope." + name] = s.slope;
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const std::string i = "[" + std::to_string(k) + "]";
      v["error." + name + i] = s.points[k].error;
      v["rays." + name + i] = s.points[k].rays;
      v["seconds." + name + i] = s.points[k].seconds;
    }
    const SamplingPoint& last = s.points.back();
    v["error." + name] = last.error;
    v["rays." + name] = last.rays;
    v["seconds." + name] = last.seconds;
    v["gain." + name] = last.error > 0 ? plain.points.back().error / last.error : 0.0;
    v["error-ratio." + name] = errorRatioAtEqualRays(plain, s);
  }
  v["seeds"] = o.seeds;
  v["rays-per-iteration"] = static_cast<double>(o.raysPerIteration.back());
  for (const SamplingSeries& s : *series)
    if (s.variant.controlVariate) v["rowsum-rays"] = s.points.back().rowSumRays;
  r.sampling = std::move(series);
}

}  // namespace rt::lesson::detail
