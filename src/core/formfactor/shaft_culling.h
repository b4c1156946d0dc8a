// Which element pairs can be occluded at all? Every segment from element i to element j lies inside the
// convex hull of i and j, in front of both planes. A patch k can only block it if (1) its box overlaps the
// pair's box, (2) it reaches in front of both planes, and (3) its own plane does not have all of i and j on
// one side. In a convex enclosure no patch passes, so no ray is ever cast.
//
// Only patches with some of the scene strictly behind their plane can pass (3) at all (a room's walls never
// do); the candidates k of (1) come from a box tree over those patches, so the cost grows like the number of
// pairs times log(patches), never like patches^3. When patches are split into several elements each, the
// patch pairs' candidates are found once (in parallel) and each element pair only re-checks those.
#pragma once

#include <cstdint>
#include <vector>

#include "core/formfactor/box_tree.h"
#include "core/mesh.h"

namespace rt {

class ShaftCulling {
 public:
  explicit ShaftCulling(const Mesh& mesh);
  // False only when no element can possibly lie between i and j. Thread-safe.
  bool mayBeOccluded(int i, int j) const;
  // The same test between a point (facing `normal`, lying on patch `pointPatch` or -1) and element j: false
  // only when nothing can stand between the point and any part of j. The two-pass method's direct light is
  // exact (Lambert's formula) where this says so. Thread-safe.
  bool mayBeOccluded(const Vec3& point, const Vec3& normal, int pointPatch, int j) const;
  // False when no patch has anything strictly behind its plane: a convex enclosure, where nothing can block.
  bool anyOccluder() const { return anyOccluder_; }
  // Appends to `patches` every patch that may block some segment from i to j (the patches for which
  // mayBeOccluded answers true). Thread-safe.
  void candidates(int i, int j, std::vector<int>& patches) const;
  // The same between a point and element j (the patches for which the point's mayBeOccluded answers true).
  void candidates(const Vec3& point, const Vec3& normal, int pointPatch, int j,
                  std::vector<int>& patches) const;
  // A patch's extreme points in order around it (the convex hull of its elements' vertices).
  const std::vector<Vec3>& outline(int patch) const {
    return patches_[static_cast<std::size_t>(patch)].outline;
  }
  std::size_t patchCount() const { return patchCount_; }

 private:
  enum Side : std::uint8_t { kOn = 0, kFront = 1, kBack = 2, kBoth = 3 };
  struct PatchInfo {
    Eigen::AlignedBox3d box;
    Vec3 normal, point;
    std::vector<Vec3> outline;  // the patch's extreme points (its elements' vertices' convex hull)
  };
  std::uint8_t sideOfPatch(int k, int plane) const;    // patch k against patch plane's plane
  std::uint8_t sideOfElement(int e, int plane) const;  // element e against a patch's plane
  bool patchMayBlock(int k, int a, int b) const;       // (2) and (3) for whole patches
  std::uint8_t elementSide(int e, int k) const;        // sideOfElement(e, k) for a blocker k, from the table
  std::vector<int> patchPairCandidates(int a, int b) const;
  // Calls visit(k) for each patch k that may block some segment from element i to j, until visit returns
  // true; returns whether it did. The one test behind mayBeOccluded(i, j) and candidates().
  template <class Visit>
  bool visitBlockers(int i, int j, Visit&& visit) const;
  // The same from a point (facing `normal`, on patch `pointPatch` or -1) to element j.
  template <class Visit>
  bool visitPointBlockers(const Vec3& point, const Vec3& normal, int pointPatch, int j, Visit&& visit) const;

  const Mesh& mesh_;
  std::vector<PatchInfo> patches_;
  std::vector<int> blockers_;      // the patches with something strictly behind their plane
  std::vector<int> blockerIndex_;  // per patch: its index in blockers_, or -1 (with the tables only)
  // Per patch a and blocker t: sideOfPatch(k, a) | sideOfPatch(a, k) << 2; per element e and blocker t:
  // sideOfElement(e, k). Empty when they would be too large.
  std::vector<std::uint8_t> patchSides_, elementSides_;
  BoxTree tree_;  // over the blockers' boxes (tree index t is patch blockers_[t])
  std::vector<Eigen::AlignedBox3d> elementBoxes_;
  std::vector<int> elementPatch_;
  // Per patch pair a < b (only when patches have several elements each): the patches that may block.
  std::vector<std::vector<int>> pairCandidates_;
  std::size_t patchCount_ = 0;
  bool anyOccluder_ = false;
  double eps_ = 0;
};

}  // namespace rt
