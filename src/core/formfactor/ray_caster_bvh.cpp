// The portable back end of RayScene (ray_caster.h): a bounding-volume hierarchy of the scene's triangles,
// built by splitting at the median centre along the longest axis, and a stack traversal nearest child first.
// The triangle test is Moller and Trumbore's (1997) in double precision on the float vertices Embree gets,
// so both back ends see the same triangles and differ only in rounding on the triangles' edges.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/formfactor/ray_caster.h"

namespace rt {
namespace {

constexpr int kLeafSize = 4;

struct Box {
  std::array<float, 3> lo{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::infinity()};
  std::array<float, 3> hi{-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()};
  void extend(const float* p) {
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], p[c]);
      hi[c] = std::max(hi[c], p[c]);
    }
  }
  void extend(const Box& b) {
    extend(b.lo.data());
    extend(b.hi.data());
  }
};

struct Node {
  Box box;
  int first = 0, count = 0;   // a leaf: order[first, first + count)
  int left = -1, right = -1;  // an inner node
};

// The ray's entry and exit of a box (slab test); false when it misses within [tnear, tfar].
bool slabs(const Box& box, const double origin[3], const double inverse[3], double tnear, double tfar,
           double& entry) {
  for (int c = 0; c < 3; ++c) {
    double t0 = (box.lo[c] - origin[c]) * inverse[c];
    double t1 = (box.hi[c] - origin[c]) * inverse[c];
    if (t0 > t1) std::swap(t0, t1);
    // 0 * inf is NaN for a ray parallel to a slab through its face: max/min with the NaN second keep the
    // bound.
    tnear = std::max(tnear, t0);
    tfar = std::min(tfar, t1);
    if (tnear > tfar) return false;
  }
  entry = tnear;
  return true;
}

class BvhCaster final : public RayCaster {
 public:
  BvhCaster(const std::vector<float>& vertices, const std::vector<unsigned>& triangles)
      : vertices_(vertices), triangles_(triangles) {
    const auto count = static_cast<int>(triangles_.size() / 3);
    boxes_.resize(static_cast<std::size_t>(count));
    for (int t = 0; t < count; ++t)
      for (int k = 0; k < 3; ++k) boxes_[std::size_t(t)].extend(vertex(t, k));
    order_.resize(static_cast<std::size_t>(count));
    std::iota(order_.begin(), order_.end(), 0);
    if (count > 0) build(0, count);
  }

  bool occluded(const FloatRay& ray, const RayFilter& filter) const override {
    float t = 0;
    return traverse(ray, filter, true, t) >= 0;
  }

  int nearest(const FloatRay& ray, const RayFilter& filter, float& t) const override {
    return traverse(ray, filter, false, t);
  }

 private:
  const float* vertex(int triangle, int k) const {
    return &vertices_[3 * std::size_t(triangles_[3 * std::size_t(triangle) + std::size_t(k)])];
  }

  // Median split along the longest axis of the centres: balanced, so the depth stays below log2(n) + 1 and
  // the traversal's fixed stack suffices.
  int build(int first, int count) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Box box, centres;
    for (int k = first; k < first + count; ++k) {
      const Box& b = boxes_[std::size_t(order_[std::size_t(k)])];
      box.extend(b);
      const float c[3] = {0.5f * (b.lo[0] + b.hi[0]), 0.5f * (b.lo[1] + b.hi[1]), 0.5f * (b.lo[2] + b.hi[2])};
      centres.extend(c);
    }
    nodes_[std::size_t(index)].box = box;
    if (count <= kLeafSize) {
      nodes_[std::size_t(index)].first = first;
      nodes_[std::size_t(index)].count = count;
      return index;
    }
    int axis = 0;
    for (int c = 1; c < 3; ++c)
      if (centres.hi[c] - centres.lo[c] > centres.hi[axis] - centres.lo[axis]) axis = c;
    const int half = count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                     [&](int a, int b) {
                       const Box& p = boxes_[std::size_t(a)];
                       const Box& q = boxes_[std::size_t(b)];
                       return p.lo[axis] + p.hi[axis] < q.lo[axis] + q.hi[axis];
                     });
    const int left = build(first, half);
    const int right = build(first + half, count - half);
    nodes_[std::size_t(index)].left = left;
    nodes_[std::size_t(index)].right = right;
    return index;
  }

  // Moller-Trumbore: the ray's t at triangle `tri`, or NaN when it misses (a ray in the triangle's plane
  // misses).
  double hit(int tri, const double origin[3], const double direction[3]) const {
    const float* a = vertex(tri, 0);
    const float* b = vertex(tri, 1);
    const float* c = vertex(tri, 2);
    const Vec3 p0(a[0], a[1], a[2]);
    const Vec3 e1 = Vec3(b[0], b[1], b[2]) - p0;
    const Vec3 e2 = Vec3(c[0], c[1], c[2]) - p0;
    const Vec3 d(direction[0], direction[1], direction[2]);
    const Vec3 p = d.cross(e2);
    const double det = e1.dot(p);
    if (det == 0) return std::numeric_limits<double>::quiet_NaN();
    const double inv = 1.0 / det;
    const Vec3 s = Vec3(origin[0], origin[1], origin[2]) - p0;
    const double u = s.dot(p) * inv;
    if (u < 0 || u > 1) return std::numeric_limits<double>::quiet_NaN();
    const Vec3 q = s.cross(e1);
    const double v = d.dot(q) * inv;
    if (v < 0 || u + v > 1) return std::numeric_limits<double>::quiet_NaN();
    return e2.dot(q) * inv;
  }

  int traverse(const FloatRay& ray, const RayFilter& filter, bool any, float& tHit) const {
    if (nodes_.empty()) return -1;
    const double origin[3] = {ray.origin[0], ray.origin[1], ray.origin[2]};
    const double direction[3] = {ray.direction[0], ray.direction[1], ray.direction[2]};
    const double inverse[3] = {1.0 / direction[0], 1.0 / direction[1], 1.0 / direction[2]};
    const double tnear = ray.tnear;
    double tfar = ray.tfar;
    int best = -1;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[std::size_t(stack[--top])];
      double entry = 0;
      if (!slabs(node.box, origin, inverse, tnear, tfar, entry)) continue;
      if (node.left < 0) {
        for (int k = node.first; k < node.first + node.count; ++k) {
          const int tri = order_[std::size_t(k)];
          const double t = hit(tri, origin, direction);
          if (!(t >= tnear && t <= tfar)) continue;
          if (!filter.accepts(static_cast<unsigned>(tri), ray.direction[0], ray.direction[1],
                              ray.direction[2]))
            continue;
          best = tri;
          tfar = t;
          if (any) {
            tHit = static_cast<float>(t);
            return best;
          }
        }
        continue;
      }
      // Nearer child last, so that it is popped first and shortens tfar for the other.
      double entryLeft = 0, entryRight = 0;
      const bool left = slabs(nodes_[std::size_t(node.left)].box, origin, inverse, tnear, tfar, entryLeft);
      const bool right = slabs(nodes_[std::size_t(node.right)].box, origin, inverse, tnear, tfar, entryRight);
      if (left && right) {
        const bool leftFirst = entryLeft <= entryRight;
        stack[top++] = leftFirst ? node.right : node.left;
        stack[top++] = leftFirst ? node.left : node.right;
      } else if (left) {
        stack[top++] = node.left;
      } else if (right) {
        stack[top++] = node.right;
      }
    }
    if (best >= 0) tHit = static_cast<float>(tfar);
    return best;
  }

  std::vector<float> vertices_;
  std::vector<unsigned> triangles_;
  std::vector<Box> boxes_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace

std::unique_ptr<RayCaster> makeBvhCaster(const std::vector<float>& vertices,
                                         const std::vector<unsigned>& triangles) {
  return std::make_unique<BvhCaster>(vertices, triangles);
}

}  // namespace rt
