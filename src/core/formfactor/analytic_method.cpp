// "analytic": exact unoccluded element-to-element form factors (contour integral, horizon-clipped), computed
// once per pair and mirrored by reciprocity. Occluders are ignored; the notes count the pairs the shaft test
// could not prove unoccluded, so nobody mistakes the result for a shadowed one. "analytic-visibility": the
// same, but where the shaft test finds that something can lie between two elements the exact unoccluded value
// is multiplied by a ray-cast visible fraction (options.samples stratified point pairs). In a convex
// enclosure both are exact and no ray is cast.
#include <algorithm>
#include <atomic>
#include <memory>

#include "core/formfactor/analytic.h"
#include "core/formfactor/analytic_method.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/visibility.h"

namespace rt {
namespace {

class AnalyticMethod : public FormFactorMethod {
 public:
  explicit AnalyticMethod(bool visibility) : visibility_(visibility) {}
  std::string name() const override { return visibility_ ? "analytic-visibility" : "analytic"; }
  AccuracyKnob knob() const override {
    if (!visibility_) return {};
    return {AccuracyKnob::Field::Samples,
            "samples",
            "stratified point pairs per possibly occluded pair",
            1,
            1024,
            16};
  }
  std::string description() const override {
    return visibility_
               ? "exact contour integral per pair times a ray-cast visible fraction where the shaft test "
                 "finds possible occluders: biased where a shadow edge crosses a pair (the visible part "
                 "is not weighted by the kernel), so far less accurate than quadrature"
               : "exact contour integral per pair, ignoring every occluder";
  }
  FormFactorMatrix computeMatrix(const Mesh& mesh, const FormFactorOptions& options, Progress& progress,
                                 FormFactorStats& stats) const override {
    const ShaftCulling shafts(mesh);
    std::unique_ptr<PairVisibility> visibility;
    if (visibility_ && shafts.anyOccluder()) visibility = std::make_unique<PairVisibility>(mesh);
    std::atomic<std::size_t> occludable{0};
    const int samples = std::clamp(options.samples, 1, 1024);
    FormFactorMatrix F =
        computeReciprocalMatrix(mesh, options, progress, stats, "form factors (analytic)", [&](int i, int j) {
          PairResult result;
          const ConvexPolygon a = elementPolygon(mesh, i), b = elementPolygon(mesh, j);
          result.value = polygonToPolygonFormFactor(a.v.data(), a.count, b.v.data(), b.count);
          if (result.value > 0 && shafts.mayBeOccluded(i, j)) {
            result.needsVisibility = true;
            ++occludable;
            if (visibility) {
              result.value *= visibility->fraction(i, j, samples, options.seed);
              result.rays = static_cast<std::size_t>(samples);
            }
          }
          return result;
        });
    const std::size_t occluded = occludable.load();
    if (!visibility_) stats.pairsOccludersIgnored = occluded;
    if (!visibility_)
      stats.notes = occluded == 0
                        ? "exact: no pair can be occluded"
                        : "unoccluded: occluders ignored for " + std::to_string(occluded) +
                              " pairs whose shaft may be blocked (analytic-visibility accounts for them)";
    else if (occluded == 0)
      stats.notes = "exact: no pair can be occluded";
    else
      stats.notes = "exact unoccluded F times ray-cast visibility (" + std::to_string(samples) +
                    " rays/pair) for " + std::to_string(occluded) + " pairs whose shaft may be blocked";
    return F;
  }

 private:
  bool visibility_;
};

}  // namespace

std::unique_ptr<FormFactorMethod> makeAnalyticMethod(bool visibility) {
  return std::make_unique<AnalyticMethod>(visibility);
}

}  // namespace rt
