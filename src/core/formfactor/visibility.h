// Visibility between two elements for the methods that integrate unoccluded kernels: the shaft test decides
// whether anything can be in the way; only then rays estimate the visible fraction.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "core/formfactor/ray_scene.h"
#include "core/formfactor/shaft_culling.h"

namespace rt {

// An element's vertices copied into a fixed array (elements have 3 or 4; up to 8 are accepted).
struct ElementPolygon {
  std::array<Vec3, 8> v;
  int count = 0;
  ElementPolygon(const Mesh& mesh, int element);
  Polygon toPolygon() const { return Polygon(v.begin(), v.begin() + count); }
};

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
