// Which element pairs can be occluded at all? Every segment from element i to element j lies inside the
// convex hull of i and j, in front of both planes. A patch k can only block it if (1) its box overlaps the
// pair's box, (2) it reaches in front of both planes, and (3) its own plane does not have all of i and j on
// one side. Tested once per patch pair (few patches), then per element pair against the surviving blocker
// patches only. In a convex enclosure no patch survives, so no ray is ever cast.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace rt {

class ShaftCulling {
 public:
  explicit ShaftCulling(const Mesh& mesh);
  // False only when no element can possibly lie between i and j.
  bool mayBeOccluded(int i, int j) const;
  // Number of patch pairs with at least one potential blocker (for notes).
  std::size_t occludablePatchPairs() const;

 private:
  enum Side : std::uint8_t { kOn = 0, kFront = 1, kBack = 2, kBoth = 3 };
  struct PatchInfo {
    Eigen::AlignedBox3d box;
    Vec3 normal, point;
  };
  std::vector<PatchInfo> patches_;
  std::vector<std::vector<int>> blockers_;  // [a * P + b] -> patches that may block
  std::vector<std::uint8_t> elementSide_;   // [e * P + k]: side of element e with respect to patch k's plane
  std::vector<Eigen::AlignedBox3d> elementBoxes_;
  std::vector<int> elementPatch_;
  std::size_t patchCount_ = 0;
  double eps_ = 0;
};

}  // namespace rt
