// "raycast": area-to-area form factors by N = options.samples stratified sample pairs per element pair; the
// estimator (unoccluded Lambert from each sample point minus what the occluders hide) is in raycast_pair.h.
// Rays are cast only when the shaft between i and j can contain another element. Deterministic for a seed:
// each pair draws from its own generator seeded by (seed, i, j).
#include <algorithm>
#include <memory>

#include "core/formfactor/analytic_method.h"
#include "core/formfactor/local_lines.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/raycast_pair.h"
#include "core/formfactor/sampling.h"
#include "core/formfactor/visibility.h"

namespace rt {
namespace {

class RaycastMethod : public FormFactorMethod {
 public:
  std::string name() const override { return "raycast"; }
  AccuracyKnob knob() const override {
    return {AccuracyKnob::Field::Samples, "samples", "stratified sample pairs per element pair", 1, 1024, 16};
  }
  std::string description() const override {
    return "N stratified sample pairs per element pair: Lambert point-to-element less the kernel of the "
           "sample pairs a ray finds hidden";
  }
  FormFactorMatrix computeMatrix(const Mesh& mesh, const FormFactorOptions& options, Progress& progress,
                                 FormFactorStats& stats) const override {
    const PairVisibility visibility(mesh);
    const int samples = std::clamp(options.samples, 1, 1024);
    auto integrate = [&](int i, int j) {
      return estimateRaycastPair(mesh, visibility, i, j, samples, options.seed);
    };
    FormFactorMatrix F =
        computeReciprocalMatrix(mesh, options, progress, stats, "form factors (raycast)",
                                [&](int i, int j) { return fromSmallerElement(mesh, i, j, integrate); });
    stats.notes =
        std::to_string(samples) +
        " stratified samples/pair: Lambert point-to-element, less the kernel of the hidden sample pairs "
        "where the shaft may be blocked";
    return F;
  }
};

// "montecarlo": local lines / form-factor sampling (local_lines.h). From each element i, N = options.samples
// rays leave uniformly chosen points in cosine-distributed directions; the fraction whose first hit is the
// front of element j estimates F_ij. Unbiased, noisy: each entry has variance F(1-F)/N, reported as the RMS
// standard error.
class MonteCarloMethod : public FormFactorMethod {
 public:
  std::string name() const override { return "montecarlo"; }
  AccuracyKnob knob() const override {
    return {AccuracyKnob::Field::Samples,
            "samples",
            "cosine-distributed rays leaving each element",
            1,
            1000000,
            16};
  }
  std::string description() const override {
    return "cosine-distributed rays from uniform points on each element; N_ij / N_i estimates F_ij";
  }
  FormFactorMatrix computeMatrix(const Mesh& mesh, const FormFactorOptions& options, Progress& progress,
                                 FormFactorStats& stats) const override {
    const RayScene rays(mesh);
    const auto n = static_cast<Eigen::Index>(mesh.size());
    const int samples = std::max(1, options.samples);
    FormFactorMatrix F = zeroFormFactorMatrix(n);
    forEachRow(mesh.size(), options, progress, "form factors (montecarlo)", stats,
               [&](int i, RowCounters& counters) {
                 for (const LocalLine& line :
                      shootLocalLines(mesh, rays, i, samples, options.seed, options.sampling))
                   if (line.hit >= 0) F(i, line.hit) += 1;  // whole counts: exact up to 2^53
                 counters.raysCast += static_cast<std::size_t>(samples);
                 // Hits are counted whole and divided once: adding 1/N per hit drifts by rounding, and
                 // over millions of rays a row of a closed scene came out above 1.
                 for (Eigen::Index j = 0; j < n; ++j) {
                   const double f = F(i, j) /= samples;
                   if (f > 0) {
                     ++counters.pairsComputed;
                     counters.varianceSum += f * (1 - f) / samples;
                   }
                 }
               });
    stats.notes = std::to_string(samples) + " cosine-distributed " +
                  (options.sampling == LineSampling::Sobol ? "Sobol " : "") + "rays/element";
    return F;
  }

 protected:
  void checkRows(const Mesh&, const FormFactorOptions&, const FormFactorMatrix&, const RowSums& rows,
                 FormFactorStats&) const override {
    checkRowSumsAtMost(rows, 1.0, "montecarlo");  // each ray lands on at most one element
  }
};

}  // namespace

std::unique_ptr<FormFactorMethod> makeRaycastMethod() {
  return std::make_unique<RaycastMethod>();
}
std::unique_ptr<FormFactorMethod> makeMonteCarloMethod() {
  return std::make_unique<MonteCarloMethod>();
}

}  // namespace rt
