#include "core/formfactor/box_tree.h"

#include <algorithm>
#include <numeric>

namespace rt {
namespace {

constexpr int kLeafSize = 4;

}  // namespace

BoxTree::BoxTree(std::vector<Eigen::AlignedBox3d> boxes) : boxes_(std::move(boxes)) {
  order_.resize(boxes_.size());
  std::iota(order_.begin(), order_.end(), 0);
  if (!boxes_.empty()) {
    nodes_.reserve(2 * boxes_.size() / kLeafSize + 2);
    build(0, static_cast<int>(boxes_.size()));
  }
}

// Median split along the longest axis of the centres: a balanced tree, so the depth stays below
// log2(n / kLeafSize) + 1 and the query's fixed stack of 64 suffices for any count.
int BoxTree::build(int first, int count) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  Eigen::AlignedBox3d box, centres;
  for (int k = first; k < first + count; ++k) {
    const auto& b = boxes_[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])];
    box.extend(b);
    centres.extend(b.center());
  }
  nodes_[static_cast<std::size_t>(index)].box = box;
  if (count <= kLeafSize) {
    // A leaf's boxes in index order: nth_element leaves each half in an order of its standard library's
    // choosing, and the order a query visits them in is the order of the callers' sums.
    std::sort(order_.begin() + first, order_.begin() + first + count);
    nodes_[static_cast<std::size_t>(index)].first = first;
    nodes_[static_cast<std::size_t>(index)].count = count;
    return index;
  }
  int axis = 0;
  centres.diagonal().maxCoeff(&axis);
  const auto begin = order_.begin() + first, middle = begin + count / 2, end = begin + count;
  // Equal centres (a regular mesh has many) in index order: the halves are then the same sets with every
  // standard library, and so is the tree (libstdc++ natively, libc++ in WebAssembly).
  std::nth_element(begin, middle, end, [&](int a, int b) {
    const double ca = boxes_[static_cast<std::size_t>(a)].center()[axis],
                 cb = boxes_[static_cast<std::size_t>(b)].center()[axis];
    return ca < cb || (ca == cb && a < b);
  });
  const int left = build(first, count / 2);
  const int right = build(first + count / 2, count - count / 2);
  nodes_[static_cast<std::size_t>(index)].left = left;
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

}  // namespace rt
