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
    nodes_[static_cast<std::size_t>(index)].first = first;
    nodes_[static_cast<std::size_t>(index)].count = count;
    return index;
  }
  int axis = 0;
  centres.diagonal().maxCoeff(&axis);
  const auto begin = order_.begin() + first, middle = begin + count / 2, end = begin + count;
  std::nth_element(begin, middle, end, [&](int a, int b) {
    return boxes_[static_cast<std::size_t>(a)].center()[axis] <
           boxes_[static_cast<std::size_t>(b)].center()[axis];
  });
  const int left = build(first, count / 2);
  const int right = build(first + count / 2, count - count / 2);
  nodes_[static_cast<std::size_t>(index)].left = left;
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

}  // namespace rt
