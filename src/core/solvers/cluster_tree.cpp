#include "core/solvers/cluster_tree.h"

#include <algorithm>

namespace rt {

ClusterTree::ClusterTree(const Mesh& mesh, const RgbField& reflectance) {
  const int n = static_cast<int>(mesh.elements.size());
  order_.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) order_[static_cast<std::size_t>(i)] = i;
  leafOf_.assign(static_cast<std::size_t>(n), -1);
  if (n == 0) return;
  nodes_.reserve(2 * static_cast<std::size_t>(n) - 1);
  build(mesh, reflectance, 0, n);
  cumulativeArea_.resize(static_cast<std::size_t>(n));
  double total = 0;
  for (int k = 0; k < n; ++k)
    cumulativeArea_[static_cast<std::size_t>(k)] = total +=
        mesh.elements[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])].area;
}

// Preorder: the node is pushed before its children, so a child's index is always larger than its parent's.
int ClusterTree::build(const Mesh& mesh, const RgbField& reflectance, int first, int count) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  ClusterNode node;
  node.first = first;
  node.count = count;
  Eigen::AlignedBox3d centroids;
  Vec3 weighted = Vec3::Zero();
  for (int k = first; k < first + count; ++k) {
    const int e = order_[static_cast<std::size_t>(k)];
    const Element& element = mesh.elements[static_cast<std::size_t>(e)];
    for (const int v : element.vertices) node.box.extend(mesh.vertices[static_cast<std::size_t>(v)]);
    centroids.extend(element.centroid);
    weighted += element.area * element.centroid;
    node.area += element.area;
    node.rhoMax = std::max(node.rhoMax, static_cast<float>(reflectance.row(e).maxCoeff()));
  }
  node.centroid = node.area > 0 ? Vec3(weighted / node.area) : node.box.center();
  // The sphere about the area-weighted centroid (not the box's centre) that holds the whole box.
  for (int corner = 0; corner < 8; ++corner)
    node.radius = std::max(
        node.radius,
        (node.box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)) - node.centroid).norm());
  if (count == 1) {
    node.element = order_[static_cast<std::size_t>(first)];
    leafOf_[static_cast<std::size_t>(node.element)] = index;
    nodes_[static_cast<std::size_t>(index)] = node;
    return index;
  }
  int axis = 0;
  centroids.sizes().maxCoeff(&axis);
  const int half = count / 2;
  auto begin = order_.begin() + first;
  std::nth_element(begin, begin + half, begin + count, [&](int a, int b) {
    const double ca = mesh.elements[static_cast<std::size_t>(a)].centroid(axis);
    const double cb = mesh.elements[static_cast<std::size_t>(b)].centroid(axis);
    return ca < cb || (ca == cb && a < b);  // ties by index: the same tree on every platform
  });
  node.left = build(mesh, reflectance, first, half);
  node.right = build(mesh, reflectance, first + half, count - half);
  nodes_[static_cast<std::size_t>(index)] = node;
  return index;
}

int ClusterTree::sampleElement(int k, double u) const {
  const ClusterNode& node = this->node(k);
  if (node.count == 1) return order_[static_cast<std::size_t>(node.first)];
  const double before = node.first > 0 ? cumulativeArea_[static_cast<std::size_t>(node.first - 1)] : 0.0;
  const double target = before + u * node.area;
  const auto begin = cumulativeArea_.begin() + node.first;
  const auto end = begin + node.count;
  const auto it = std::upper_bound(begin, end, target);
  const auto position = std::min<std::ptrdiff_t>(it - cumulativeArea_.begin(), node.first + node.count - 1);
  return order_[static_cast<std::size_t>(position)];
}

std::size_t ClusterTree::bytes() const {
  return nodes_.capacity() * sizeof(ClusterNode) + order_.capacity() * sizeof(int) +
         cumulativeArea_.capacity() * sizeof(double) + leafOf_.capacity() * sizeof(int);
}

}  // namespace rt
