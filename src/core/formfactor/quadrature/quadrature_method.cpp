// "quadrature": every entry to an absolute tolerance, one knob (`tolerance`) setting the cost.
//
//   F_ij = U_ij - H_ij,  U_ij = (1/A_i) int_i F(dA_x -> j) dA_x,  H_ij = (1/A_i) int_i F(dA_x -> hidden j)
//   dA_x
//
// U, the unoccluded form factor: pairs closer than one source size are given the exact contour integral (its
// cost does not depend on the tolerance, and quadrature would need many points there). All others get
// Gauss-Legendre quadrature of Lambert's formula over the source, the order read off an a-priori bound for
// each panel (source_panels.h), panels split where the order would exceed 8. A far pair at a loose
// tolerance gets one point (the centroid rule) only when the bound allows it.
//
// H, the hidden part, only where occluders survive the shaft test, the blocks' shadow regions and the
// clipper's own tests: the hidden part of the receiver from each point, clipped in double precision, and
// integrated over cells of the source cut along the visibility events where there is one occluder, by
// globally adaptive rules with guards elsewhere (quadrature_pair.h). Depth and points per pair are
// bounded; pairs that reach the bound are counted in the notes.
//
// Both halves are computed from the smaller element of a pair (pair_matrix.h), so the tolerance holds for
// F_ij and F_ji alike. Rows are spread over the cores by TBB's work stealing.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "core/formfactor/analytic_method.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/quadrature/hidden_integral.h"
#include "core/formfactor/quadrature/quadrature_pair.h"
#include "core/formfactor/quadrature/quadrature_scene.h"
#include "core/formfactor/shaft_culling.h"
#include "core/parallel.h"

namespace rt {
namespace {

class QuadratureMethod : public FormFactorMethod {
 public:
  std::string name() const override { return "quadrature"; }
  AccuracyKnob knob() const override {
    return {AccuracyKnob::Field::Tolerance,
            "ff-tolerance",
            "absolute error allowed in each form factor",
            1e-9,
            0.1,
            1e-5};
  }
  double entryErrorBound(double, const FormFactorOptions& options) const override {
    return options.tolerance;
  }
  std::string description() const override {
    return "every entry to an absolute --ff-tolerance: exact contour integral for near pairs, Gauss "
           "quadrature "
           "of Lambert's formula with an a-priori order elsewhere, the hidden part clipped per point in "
           "double precision and integrated over cells cut along the visibility events";
  }

  bool readsOnlyItsKnob() const override { return true; }
  FormFactorMatrix computeMatrix(const Mesh& mesh, const FormFactorOptions& options, Progress& progress,
                                 FormFactorStats& stats) const override {
    const ShaftCulling shafts(mesh);
    const QuadratureScene scene(mesh, shafts);
    const double tolerance = std::clamp(options.tolerance, 1e-12, 0.5);
    // Looked up once per pair, by the worker's index: one scratch pair per worker, no lock.
    PerWorker<QuadraturePair> pairs(std::cref(scene), tolerance);
    FormFactorMatrix F = computeReciprocalMatrix(
        mesh, options, progress, stats, "form factors (quadrature)", [&](int i, int j) {
          QuadraturePair& pair = pairs.local();
          return fromSmallerElement(mesh, i, j, [&](int a, int b) { return pair(a, b, i); });
        });
    QuadraturePair::Counts total;
    pairs.forEach([&](const QuadraturePair& pair) { total += pair.counts(); });
    std::string routes;
    for (int r = 0; r < kQuadratureRoutes; ++r)
      if (const long count = total.routes[static_cast<std::size_t>(r)]; count > 0)
        routes += (routes.empty() ? "" : ", ") + std::string(routeName(static_cast<QuadratureRoute>(r))) +
                  " " + std::to_string(count);
    char line[256];
    std::snprintf(
        line, sizeof line,
        "absolute tolerance %.3g: %ld point evaluations (%ld with the receiver clipped, %ld of them "
        "placed from their cell's hidden form), %ld exact "
        "contour integrals, %ld pairs with occluders clipped per point (%ld of them wholly hidden)",
        tolerance, total.points, total.clipped, total.placed, total.contours, total.occludedPairs,
        total.hiddenPairs);
    stats.notes = "routes: " + (routes.empty() ? std::string("none") : routes) + "; " + line;
    stats.notes += ", " + std::to_string(scene.solids.size()) + " closed convex solids, " +
                   std::to_string(total.eventPairs) +
                   " pairs integrated over cells cut along visibility events (" +
                   std::to_string(total.apartPairs) + " of them solid by solid, their shadows apart)";
    if (scene.solids.size() >= 2 && !scene.apartTested())
      stats.notes += ", no proof that two solids' shadows stay apart (" +
                     std::to_string(scene.solids.size()) + " solids on " + std::to_string(mesh.size()) +
                     " elements would need a table of more than " +
                     std::to_string(QuadratureScene::kMaxApartEntries) +
                     " entries): pairs that several solids shade take the adaptive rules";
    if (total.budgetPairs > 0)
      stats.notes += ", " + std::to_string(total.budgetPairs) + " pairs reached the work bound (depth " +
                     std::to_string(HiddenIntegral::kMaxDepth) + ", " +
                     std::to_string(HiddenIntegral::kMaxPoints) + " points) before the tolerance";
    return F;
  }
};

}  // namespace

std::unique_ptr<FormFactorMethod> makeQuadratureMethod() {
  return std::make_unique<QuadratureMethod>();
}

}  // namespace rt
