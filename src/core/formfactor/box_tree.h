// A bounding-volume hierarchy over axis-aligned boxes: which of them overlap a query box, in time that grows
// with the answer and the logarithm of the count instead of the count. The shaft test asks it for the patches
// that could stand between two elements; testing every patch for every pair made its setup cubic.
#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace rt {

class BoxTree {
 public:
  BoxTree() = default;
  explicit BoxTree(std::vector<Eigen::AlignedBox3d> boxes);

  // Calls visit(index) for every box that overlaps `query` by more than `eps` on every axis (boxes that
  // merely touch do not count); stops early when visit returns true, and then returns true.
  template <class Visit>
  bool anyOverlapping(const Eigen::AlignedBox3d& query, double eps, Visit&& visit) const;

  std::size_t size() const { return boxes_.size(); }

  // Strict overlap by more than eps on every axis: boxes that merely touch (a wall and the floor) do not
  // count.
  static bool overlaps(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, double eps) {
    return (a.min().array() < b.max().array() - eps).all() && (b.min().array() < a.max().array() - eps).all();
  }

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    int first = 0, count = 0;   // a leaf: order_[first, first + count)
    int left = -1, right = -1;  // an inner node: its children
  };
  int build(int first, int count);

  std::vector<Eigen::AlignedBox3d> boxes_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

template <class Visit>
bool BoxTree::anyOverlapping(const Eigen::AlignedBox3d& query, double eps, Visit&& visit) const {
  if (nodes_.empty()) return false;
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
    if (!overlaps(node.box, query, eps)) continue;
    if (node.left < 0) {
      for (int k = node.first; k < node.first + node.count; ++k) {
        const int index = order_[static_cast<std::size_t>(k)];
        if (overlaps(boxes_[static_cast<std::size_t>(index)], query, eps) && visit(index)) return true;
      }
      continue;
    }
    stack[top++] = node.left;
    stack[top++] = node.right;
  }
  return false;
}

}  // namespace rt
