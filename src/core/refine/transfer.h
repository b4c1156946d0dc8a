// Energy transfer between small pieces of surface, for the refining meshers: a point-to-polygon Lambert form
// factor (exact for an unoccluded polygon seen from a point), ray-polygon visibility against the scene's
// patches, and an element-to-element estimate built from both. The meshers call these for every new row and
// column of F and for every hierarchical link, so they favour speed: the polygon side is integrated in closed
// form, only visibility is sampled.
#pragma once

#include <atomic>
#include <utility>
#include <vector>

#include "core/scene.h"

namespace rt {

// Stratified points over a convex polygon with their area weights (summing to 1): the polygon is
// fan-triangulated and each triangle gets perSide^2 points of an area-uniform square-to-triangle map at cell
// centres. perSide = 1 on a triangle or quad gives its centroid alone.
struct SurfaceSample {
  Vec3 point;
  double weight;
};
std::vector<SurfaceSample> stratifiedSamples(const Polygon& P, int perSide);

// Ray-polygon occlusion against the patches of a scene (all of them two-sided blockers). For each pair of
// patches the candidate blockers are precomputed: those whose bounds meet the pair's bounds and that reach in
// front of both.
class VisibilityOracle {
 public:
  explicit VisibilityOracle(const Scene& scene);
  // True when the open segment a-b crosses no patch other than the two given ones.
  bool segmentClear(const Vec3& a, const Vec3& b, int patchA, int patchB) const;
  // Fraction of the target points visible from x (x on patchFrom, targets on patchTo).
  double visibleFraction(const Vec3& x, const std::vector<SurfaceSample>& targets, int patchFrom,
                         int patchTo) const;
  bool mayBeOccluded(int patchA, int patchB) const { return !candidates(patchA, patchB).empty(); }
  std::size_t raysCast() const { return rays_.load(); }

 private:
  struct Blocker {
    Polygon vertices;
    Vec3 normal;
    double offset;  // normal . p for p on the plane
  };
  const std::vector<int>& candidates(int a, int b) const { return candidates_[a * patches_ + b]; }
  bool crosses(const Blocker& blocker, const Vec3& a, const Vec3& d) const;

  int patches_ = 0;
  std::vector<Blocker> blockers_;
  std::vector<std::vector<int>> candidates_;  // patches_ x patches_
  mutable std::atomic<std::size_t> rays_{0};  // statistics only
};

// A planar convex piece of one scene patch: what the refining meshers exchange energy between.
struct SurfacePiece {
  const Polygon* polygon = nullptr;
  Vec3 normal;
  Vec3 centroid;
  double area = 0;
  int patch = -1;
};

struct TransferOptions {
  int visibilitySamples =
      16;                   // points on the source polygon tested from each receiver point (rounded to k^2)
  double nearFactor = 2.0;  // receiver integrated with 3x3 points when centroids are closer than this x sizes
};

// (F_ab, F_ba) for two pieces. The point-to-polygon integral runs from the smaller piece (sampled) to the
// larger (closed form); the other direction follows from reciprocity, so A_a F_ab = A_b F_ba holds exactly.
std::pair<double, double> pieceFormFactors(const SurfacePiece& a, const SurfacePiece& b,
                                           const VisibilityOracle& visibility,
                                           const TransferOptions& options);

// The unoccluded point-to-polygon form factor from a's centroid to b (and the reciprocal one): a cheap upper
// estimate used by the hierarchical refinement oracle.
std::pair<double, double> pieceFormFactorEstimate(const SurfacePiece& a, const SurfacePiece& b);

}  // namespace rt
