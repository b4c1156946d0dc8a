// Visibility between two elements for the methods that integrate unoccluded kernels: the shaft test decides
// whether anything can be in the way; only then rays estimate the visible fraction.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "core/formfactor/ray_scene.h"
#include "core/formfactor/shaft_culling.h"
#include "core/geometry/convex_polygon.h"

namespace rt {

// An element's corners as a convex polygon (elements have 3 or 4; more go on the polygon's heap).
ConvexPolygon elementPolygon(const Mesh& mesh, int element);

class PairVisibility {
 public:
  explicit PairVisibility(const Mesh& mesh);
  bool mayBeOccluded(int i, int j) const { return shafts_.mayBeOccluded(i, j); }
  // Fraction of `samples` stratified point pairs (x on i, y on j) whose segment is unblocked; deterministic
  // for a seed.
  double fraction(int i, int j, int samples, std::uint64_t seed) const;
  const RayScene& rays() const { return *rays_; }
  const ShaftCulling& shafts() const { return shafts_; }

 private:
  const Mesh& mesh_;
  ShaftCulling shafts_;
  std::unique_ptr<RayScene> rays_;
};

}  // namespace rt
