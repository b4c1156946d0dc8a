#include "core/solvers/cluster_directions.h"

#include <cmath>
#include <map>
#include <utility>

namespace rt {
namespace {

// The six axis weights max(0, s n_a) / sum |n_a| of a unit normal, in the order +x, -x, +y, -y, +z, -z.
std::array<double, 6> axisWeights(const Vec3& n) {
  const double sum = n.cwiseAbs().sum();
  const double w = sum > 0 ? 1.0 / sum : 0.0;
  return {w * std::max(0.0, n.x()),  w * std::max(0.0, -n.x()), w * std::max(0.0, n.y()),
          w * std::max(0.0, -n.y()), w * std::max(0.0, n.z()),  w * std::max(0.0, -n.z())};
}

// The axis class of a normal within 1e-6 of an axis, else -1 (the mesh's normals carry the rounding of the
// input's coordinates; the error of taking such a normal as the axis is of that size too).
int axisClass(const Vec3& n) {
  constexpr double kSlack = 1e-6;
  for (int a = 0; a < 3; ++a)
    if (std::abs(n[a]) >= 1.0 - kSlack * kSlack) return 2 * a + (n[a] < 0 ? 1 : 0);
  return -1;
}

// Normals equal to about 1e-5 share a key: planes of one slope cut into elements get one class.
using Key = std::array<long long, 3>;
Key keyOf(const Vec3& n) {
  return {std::llround(n.x() * 1e5), std::llround(n.y() * 1e5), std::llround(n.z() * 1e5)};
}

}  // namespace

ClusterDirections::ClusterDirections(const Mesh& mesh) {
  normals_ = {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()};
  const std::size_t n = mesh.elements.size();
  class_.assign(n, 0);
  // The tilted normals by key (a std::map: the same classes, in the same order, on every platform).
  struct Group {
    double area = 0;
    Vec3 sum = Vec3::Zero();
    int cls = -1;
  };
  std::map<Key, Group> groups;
  double total = 0;
  for (std::size_t e = 0; e < n; ++e) {
    const Element& element = mesh.elements[e];
    total += element.area;
    const Vec3 normal = element.normal.normalized();
    if (axisClass(normal) >= 0) continue;
    Group& g = groups[keyOf(normal)];
    g.area += element.area;
    g.sum += element.area * normal;
  }
  std::vector<std::pair<double, Group*>> ranked;
  for (auto& [key, g] : groups)
    if (g.area >= 0.01 * total) ranked.emplace_back(g.area, &g);
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t k = 0; k < ranked.size() && k < std::size_t(kExtraClasses); ++k) {
    ranked[k].second->cls = classes();
    normals_.push_back(ranked[k].second->sum.normalized());
  }
  for (std::size_t e = 0; e < n; ++e) {
    const Vec3 normal = mesh.elements[e].normal.normalized();
    const int axis = axisClass(normal);
    if (axis >= 0) {
      class_[e] = axis;
      continue;
    }
    const int cls = groups[keyOf(normal)].cls;
    if (cls >= 0) {
      class_[e] = cls;
      continue;
    }
    class_[e] = -1 - static_cast<int>(spread_.size());
    spread_.push_back(axisWeights(normal));
  }
}

void ClusterDirections::spread(int e, const double value[3], double* row) const {
  const int cls = class_[static_cast<std::size_t>(e)];
  if (cls >= 0) {
    for (int ch = 0; ch < 3; ++ch) row[3 * cls + ch] += value[ch];
    return;
  }
  const auto& w = spread_[static_cast<std::size_t>(-1 - cls)];
  for (int c = 0; c < kAxisClasses; ++c)
    for (int ch = 0; ch < 3; ++ch) row[3 * c + ch] += w[static_cast<std::size_t>(c)] * value[ch];
}

void ClusterDirections::pick(int e, const double* row, double out[3]) const {
  const int cls = class_[static_cast<std::size_t>(e)];
  if (cls >= 0) {
    for (int ch = 0; ch < 3; ++ch) out[ch] = row[3 * cls + ch];
    return;
  }
  const auto& w = spread_[static_cast<std::size_t>(-1 - cls)];
  for (int ch = 0; ch < 3; ++ch) out[ch] = 0;
  for (int c = 0; c < kAxisClasses; ++c)
    for (int ch = 0; ch < 3; ++ch) out[ch] += w[static_cast<std::size_t>(c)] * row[3 * c + ch];
}

void ClusterDirections::radiate(const double* D, const Vec3& w, double out[3]) const {
  for (int ch = 0; ch < 3; ++ch) out[ch] = 0;
  // The axis classes: the one facing w along each axis, by |w_a|.
  for (int a = 0; a < 3; ++a) {
    const double* d = D + 3 * (2 * a + (w[a] < 0 ? 1 : 0));
    const double weight = std::abs(w[a]);
    for (int ch = 0; ch < 3; ++ch) out[ch] += weight * d[ch];
  }
  for (int c = kAxisClasses; c < classes(); ++c) {
    const double weight = normals_[static_cast<std::size_t>(c)].dot(w);
    if (weight <= 0) continue;
    for (int ch = 0; ch < 3; ++ch) out[ch] += weight * D[3 * c + ch];
  }
}

void ClusterDirections::receive(const double E[3], const Vec3& u, double* bins) const {
  for (int a = 0; a < 3; ++a) {
    double* b = bins + 3 * (2 * a + (u[a] < 0 ? 1 : 0));
    const double weight = std::abs(u[a]);
    for (int ch = 0; ch < 3; ++ch) b[ch] += weight * E[ch];
  }
  for (int c = kAxisClasses; c < classes(); ++c) {
    const double weight = normals_[static_cast<std::size_t>(c)].dot(u);
    if (weight <= 0) continue;
    for (int ch = 0; ch < 3; ++ch) bins[3 * c + ch] += weight * E[ch];
  }
}

}  // namespace rt
