// The rays stage's comparison of local lines with a reference: the `from` element's Monte Carlo row (the
// fraction of its lines that land first on each surface) beside the same row of the reference's F, with the
// binomial standard error of each fraction.
#include <algorithm>
#include <cmath>
#include <limits>

#include "lesson/step_stages.h"

namespace rt::lesson::detail {

void addLocalLineValues(StageContext& c) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  if (p.reference.empty() || !r.F) return;
  if (r.method != "montecarlo")
    c.fail(
        "reference",
        "comparing with a reference counts local lines: the step needs method: montecarlo, not " + r.method);
  FormFactorStats referenceStats;
  r.referenceF = c.formFactors(r.mesh, p.reference, "reference", referenceStats);
  addFormFactorValues(r, *r.referenceF, ".reference");
  const double lines = c.formFactorOptions.samples;
  const auto source = static_cast<Eigen::Index>(r.sourceElement);
  std::vector<double> hit(r.scene.surfaces.size(), 0.0), exact(r.scene.surfaces.size(), 0.0);
  for (std::size_t e = 0; e < r.mesh.size(); ++e) {
    const int s = r.scene.patches[r.mesh.elements[e].patch].surface;
    hit[static_cast<std::size_t>(s)] += (*r.F)(source, static_cast<Eigen::Index>(e));
    exact[static_cast<std::size_t>(s)] += (*r.referenceF)(source, static_cast<Eigen::Index>(e));
  }
  double worst = 0, hitSum = 0, exactSum = 0;
  for (std::size_t s = 0; s < hit.size(); ++s) {
    const std::string& name = r.scene.surfaces[s].name;
    // Binomial: each line lands on the surface or not, with the probability the reference gives.
    const double se = std::sqrt(std::max(0.0, hit[s] * (1.0 - hit[s])) / lines);
    r.values["lines." + name] = hit[s];
    r.values["lines." + name + ".reference"] = exact[s];
    r.values["lines-se." + name] = se;
    const double z = se > 0               ? std::abs(hit[s] - exact[s]) / se
                     : hit[s] == exact[s] ? 0.0
                                          : std::numeric_limits<double>::infinity();
    r.values["lines-z." + name] = z;
    worst = std::max(worst, z);
    hitSum += hit[s];
    exactSum += exact[s];
  }
  r.values["lines"] = lines;
  r.values["lines-z.max"] = worst;
  r.values["lines.escaped"] = std::max(0.0, 1.0 - hitSum);
  r.values["lines.escaped.reference"] = std::max(0.0, 1.0 - exactSum);
}

}  // namespace rt::lesson::detail
