// Pair set-up for one entry F_ij: the facing test (one element entirely behind the other's plane -> F = 0)
// and shaft culling (Haines & Wallace 1991 in spirit): only elements meeting the convex hull of the two
// elements can block a ray between them. The hull is bounded by the two element planes and by the planes
// through an edge of one element and a vertex of the other that have both elements on one side. The tests are
// conservative: an element is dropped only when it lies on the far side of such a plane (touching it blocks
// no light), with a tiny relative tolerance.
#pragma once

#include <algorithm>
#include <vector>

#include "core/formfactor/box_tree.h"
#include "core/mesh.h"

namespace rt::exact {

struct PairGeometry {
  int source = -1, receiver = -1;
  Polygon sourcePolygon, receiverPolygon;
  Vec3 sourceNormal, receiverNormal;  // unit
  bool facing = false;                // some of each element lies strictly in front of the other
  Polygon integrationDomain;          // source clipped to the receiver's front half-space
  std::vector<int> occluders;         // shaft candidates
  std::vector<Polygon> occluderPolygons;
  std::vector<Polygon> blockers;  // the same merged per patch, none inside another (blockers.h)
  double scale = 1;               // length scale of the pair (for relative tolerances)
};

// Relative tolerance of the double-precision culling and classification tests.
inline constexpr double kGeometricEpsilon = 1e-11;

// Every element's polygon and box, and a box tree over them, built once per mesh: a pair's shaft then
// looks only at the elements whose boxes meet its own, instead of building and testing every element's
// polygon for every pair (n^3 work for a matrix).
class ElementIndex {
 public:
  explicit ElementIndex(const Mesh& mesh);
  const Polygon& polygon(int element) const { return polygons_[static_cast<std::size_t>(element)]; }
  const Eigen::AlignedBox3d& box(int element) const { return boxes_[static_cast<std::size_t>(element)]; }
  // The elements whose boxes meet `box` (touching counts) and that `keep` accepts, in increasing order, into
  // `out`. Filtering before sorting: most boxes a shaft meets hold elements it then drops.
  template <class Keep>
  void overlapping(const Eigen::AlignedBox3d& box, std::vector<int>& out, Keep&& keep) const {
    out.clear();
    // The tree's overlap is strict by eps on every axis; a negative eps makes touching boxes count, as
    // AlignedBox3d::intersects does.
    const double slack = 1e-9 * std::max(box.diagonal().norm(), 1e-300);
    tree_.anyOverlapping(box, -slack, [&](int k) {
      if (box.intersects(boxes_[static_cast<std::size_t>(k)]) && keep(k)) out.push_back(k);
      return false;
    });
    std::sort(out.begin(), out.end());
  }

 private:
  std::vector<Polygon> polygons_;
  std::vector<Eigen::AlignedBox3d> boxes_;
  BoxTree tree_;
};

// `index`, when given, must be of `mesh`; the result is the same with or without it.
PairGeometry setUpPair(const Mesh& mesh, int source, int receiver, bool cullOccluders = true,
                       const ElementIndex* index = nullptr);

}  // namespace rt::exact
