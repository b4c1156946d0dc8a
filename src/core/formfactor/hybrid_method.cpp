// "hybrid": each pair by the cheapest rule that is accurate for it, and rays where they buy the most.
//
//   F_ij = U_ij - H_ij
//
// U_ij is the unoccluded form factor: exact (the contour integral) for near pairs, whose centroid distance is
// under kNearRadii times the sum of the elements' radii; Lambert's point-to-polygon formula from i's centroid
// for the middle distances; the point-to-point kernel A_j cos cos / (pi r^2) between centroids beyond
// kFarRadii radii. The centroid rules err by O((r/d)^2) relative, which is small exactly where they are used,
// and the near pairs, which carry most of a matrix's norm, are exact.
//
// H_ij is what occluders hide, zero when the shaft test proves the pair unoccluded, and otherwise the
// ray-cast estimate of raycast_pair.h: N stratified sample pairs (x on i, y on j), each blocked one
// contributing A_j K(x, y). Its error is about U_ij / sqrt(N), so the squared error of the whole matrix,
// sum U^2 / N, is least for a given number of rays when N is in proportion to U: N_ij = samples * U_ij / 1 %,
// between 1 and 1024. A pair with a 10 % form factor gets ten times the rays of one with 1 %, and the many
// far pairs one ray each.
//
// Its error falls with the rays, where the hemicube's centroid rule keeps a bias that no resolution removes
// (docs/benchmarks.md has the figures).
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "core/formfactor/analytic.h"
#include "core/formfactor/analytic_method.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/sampling.h"
#include "core/formfactor/visibility.h"

namespace rt {
namespace {

constexpr double kNearRadii = 3;  // closer: exact unoccluded form factor
constexpr double kFarRadii = 6;   // farther: centroid-to-centroid kernel
constexpr int kMaxRays = 1024;

// Largest distance from the centroid to a vertex.
std::vector<double> elementRadii(const Mesh& mesh) {
  std::vector<double> radii(mesh.size());
  for (std::size_t e = 0; e < mesh.size(); ++e)
    for (int v : mesh.elements[e].vertices)
      radii[e] = std::max(radii[e], (mesh.vertices[v] - mesh.elements[e].centroid).norm());
  return radii;
}

class HybridMethod : public FormFactorMethod {
 public:
  std::string name() const override { return "hybrid"; }
  AccuracyKnob knob() const override {
    return {AccuracyKnob::Field::Samples,
            "samples",
            "rays per 1 % of an occluded pair's form factor",
            1,
            100000,
            16};
  }
  std::string description() const override {
    return "exact unoccluded F for near pairs, centroid rules for far ones; occluded pairs less a ray-cast "
           "estimate of what is hidden, rays in proportion to the form factor";
  }

  FormFactorMatrix computeMatrix(const Mesh& mesh, const FormFactorOptions& options, Progress& progress,
                                 FormFactorStats& stats) const override {
    const PairVisibility visibility(mesh);
    const std::vector<double> radii = elementRadii(mesh);
    const double raysPerUnitF = 100.0 * std::max(1, options.samples);

    auto integrate = [&](int i, int j) {
      PairResult result;
      const Element& from = mesh.elements[i];
      const Element& to = mesh.elements[j];
      const ConvexPolygon a = elementPolygon(mesh, i), b = elementPolygon(mesh, j);
      const double distance = (to.centroid - from.centroid).norm();
      const double reach = radii[i] + radii[j];
      double unoccluded;
      if (distance < kNearRadii * reach)
        unoccluded = polygonToPolygonFormFactor(a.v.data(), a.count, b.v.data(), b.count);
      else if (distance < kFarRadii * reach)
        unoccluded = pointToPolygonFormFactor(from.centroid, from.normal, b.v.data(), b.count);
      else
        unoccluded =
            std::min(1.0, to.area * pointToPointKernel(from.centroid, from.normal, to.centroid, to.normal));
      result.value = unoccluded;
      result.needsVisibility = visibility.mayBeOccluded(i, j);
      if (!result.needsVisibility || unoccluded <= 0) return result;

      const int rays = std::clamp(static_cast<int>(std::ceil(raysPerUnitF * unoccluded)), 1, kMaxRays);
      PairRandom random(options.seed, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j));
      thread_local std::vector<int> strataOfJ;
      shuffledStrata(rays, random, strataOfJ);
      const StrataGrid grid(rays);
      const PolygonSampler onI(a.v.data(), a.count), onJ(b.v.data(), b.count);
      double hidden = 0;
      for (int k = 0; k < rays; ++k) {
        const Vec2 s = grid.sample(k, random),
                   t = grid.sample(strataOfJ[static_cast<std::size_t>(k)], random);
        const Vec3 x = onI.point(s.x(), s.y()), y = onJ.point(t.x(), t.y());
        if (!visibility.rays().visible(x, y, i, j))
          hidden += pointToPointKernel(x, from.normal, y, to.normal);
      }
      result.rays = static_cast<std::size_t>(rays);
      // Clamped: hidden samples close together can overshoot a pair that is in fact fully hidden.
      result.value = std::max(0.0, unoccluded - to.area * hidden / rays);
      return result;
    };

    FormFactorMatrix F =
        computeReciprocalMatrix(mesh, options, progress, stats, "form factors (hybrid)",
                                [&](int i, int j) { return fromSmallerElement(mesh, i, j, integrate); });
    stats.notes = "exact F within " + std::to_string(static_cast<int>(kNearRadii)) +
                  " radii, centroid rules beyond; occluded pairs less a ray-cast hidden part, " +
                  std::to_string(std::max(1, options.samples)) + " rays per 1 % of form factor (1.." +
                  std::to_string(kMaxRays) + ")";
    return F;
  }
};

}  // namespace

std::unique_ptr<FormFactorMethod> makeHybridMethod() {
  return std::make_unique<HybridMethod>();
}

}  // namespace rt
