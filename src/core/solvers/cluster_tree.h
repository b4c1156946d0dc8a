// The cluster hierarchy of hierarchical radiosity with clustering (Smits, Arvo & Greenberg 1994): a binary
// tree of axis-aligned boxes over the mesh's elements, split at the median of the element centroids along
// the longest axis, down to one element per leaf. A node stands for the elements below it: their total
// area, their area-weighted centroid, the bounding sphere of their box, and the largest reflectance among
// them (what the refinement oracle needs to bound what a link can carry). Nodes are stored in preorder
// (every child after its parent), so push-pull passes are two loops over an array.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

#include "core/mesh.h"
#include "core/vec.h"

namespace rt {

struct ClusterNode {
  Eigen::AlignedBox3d box;
  Vec3 centroid;      // area-weighted centroid of the elements below
  double area = 0;    // their total area
  double radius = 0;  // half the box's diagonal: a sphere about `centroid` of twice this holds them all
  int first = 0;      // the elements below: ClusterTree::order()[first, first + count)
  int count = 0;
  int left = -1;  // children (-1 on a leaf)
  int right = -1;
  int element = -1;  // a leaf: its element
  float rhoMax = 0;  // largest reflectance of any channel of any element below
  bool leaf() const { return left < 0; }
};

class ClusterTree {
 public:
  // reflectance: n x 3, one row per element of `mesh`.
  ClusterTree(const Mesh& mesh, const RgbField& reflectance);

  const std::vector<ClusterNode>& nodes() const { return nodes_; }
  const ClusterNode& node(int k) const { return nodes_[static_cast<std::size_t>(k)]; }
  const std::vector<int>& order() const { return order_; }
  std::size_t size() const { return nodes_.size(); }
  // The node whose leaf is element e.
  int leafOf(int element) const { return leafOf_[static_cast<std::size_t>(element)]; }

  // An element below node k drawn with probability proportional to its area, from u in [0, 1).
  int sampleElement(int k, double u) const;

  // Bytes held by the tree (nodes, element order, area sums, leaf index), counted from the containers.
  std::size_t bytes() const;

 private:
  int build(const Mesh& mesh, const RgbField& reflectance, int first, int count);

  std::vector<ClusterNode> nodes_;
  std::vector<int> order_;
  std::vector<double> cumulativeArea_;  // running sum of the areas in order_
  std::vector<int> leafOf_;
};

}  // namespace rt
