// "nusselt": row i is the point form factor from element i's centroid to every element, each computed by the
// Nusselt analog (projected outline, max(options.samples, 4) segments per arc). Occluders are ignored (the
// notes say so): this method exists to show the analog at work on a whole scene, and converges to the
// centroid-point analytic value.
#include <algorithm>

#include "core/formfactor/analytic_method.h"
#include "core/formfactor/nusselt.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/visibility.h"

namespace rt {
namespace {

class NusseltMethod : public FormFactorMethod {
 public:
  std::string name() const override { return "nusselt"; }
  AccuracyKnob knob() const override {
    return {AccuracyKnob::Field::Samples,
            "samples",
            "segments per projected arc of the Nusselt outline",
            4,
            65536,
            16};
  }
  std::string description() const override {
    return "Nusselt analog from each centroid: hemisphere projection, area on the base disk (unoccluded)";
  }
  bool readsOnlyItsKnob() const override { return true; }
  FormFactorMatrix computeMatrix(const Mesh& mesh, const FormFactorOptions& options, Progress& progress,
                                 FormFactorStats& stats) const override {
    const int segments = std::max(4, options.samples);
    const auto n = static_cast<Eigen::Index>(mesh.size());
    FormFactorMatrix F = zeroFormFactorMatrix(n);
    forEachRow(mesh.size(), options, progress, "form factors (nusselt)", stats,
               [&](int i, RowCounters& counters) {
                 const Element& self = mesh.elements[i];
                 for (Eigen::Index j = 0; j < n; ++j) {
                   if (j == i) continue;
                   if (!elementsFaceEachOther(mesh, i, static_cast<int>(j))) {
                     ++counters.pairsSkippedFacing;
                     continue;
                   }
                   const ConvexPolygon b = elementPolygon(mesh, static_cast<int>(j));
                   F(i, j) = nusseltFormFactor(self.centroid, self.normal, b.v.data(), b.count, segments);
                   ++counters.pairsComputed;
                 }
               });
    stats.notes = std::to_string(segments) + " segments per projected arc, from centroids; occluders ignored";
    return F;
  }
};

}  // namespace

std::unique_ptr<FormFactorMethod> makeNusseltMethod() {
  return std::make_unique<NusseltMethod>();
}

}  // namespace rt
