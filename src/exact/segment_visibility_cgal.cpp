// Exact segment visibility V(x, y): a CGAL AABB tree over the elements' triangles, queried with exact
// predicates (Exact_predicates_inexact_constructions_kernel: inputs are doubles,
// do_intersect/has_on/orientation are exact). The second of the two translation units of the library that
// include CGAL.
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <iterator>

#include "core/polygon.h"
#include "exact/segment_visibility.h"

namespace rt::exact {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Traits = CGAL::AABB_traits<Kernel, Primitive>;
using Tree = CGAL::AABB_tree<Traits>;

Point toPoint(const Vec3& v) {
  return Point(v.x(), v.y(), v.z());
}

}  // namespace

struct SegmentVisibility::Impl {
  std::vector<Triangle> triangles;
  std::vector<int> owner;  // element of each triangle
  Tree tree;
};

SegmentVisibility::SegmentVisibility(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    for (const Polygon& t : fanTriangulate(mesh.polygon(static_cast<int>(e)))) {
      const Triangle triangle(toPoint(t[0]), toPoint(t[1]), toPoint(t[2]));
      if (triangle.is_degenerate()) continue;
      impl_->triangles.push_back(triangle);
      impl_->owner.push_back(static_cast<int>(e));
    }
  }
  impl_->tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
  impl_->tree.build();
}

SegmentVisibility::~SegmentVisibility() = default;

std::vector<int> SegmentVisibility::blockers(const Vec3& x, const Vec3& y, int ignoreA, int ignoreB) const {
  std::vector<int> result;
  const Point p = toPoint(x), q = toPoint(y);
  if (p == q) return result;
  std::vector<Primitive::Id> hits;
  impl_->tree.all_intersected_primitives(Segment(p, q), std::back_inserter(hits));
  for (const Primitive::Id& id : hits) {
    const auto index = static_cast<std::size_t>(id - impl_->triangles.cbegin());
    const int element = impl_->owner[index];
    if (element == ignoreA || element == ignoreB) continue;
    const Triangle& t = *id;
    // Touching only at an end point, or grazing within the triangle's plane, blocks no light (measure zero).
    if (CGAL::orientation(t[0], t[1], t[2], p) == CGAL::COPLANAR &&
        CGAL::orientation(t[0], t[1], t[2], q) == CGAL::COPLANAR)
      continue;
    if (t.has_on(p) || t.has_on(q)) continue;
    result.push_back(element);
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

bool SegmentVisibility::visible(const Vec3& x, const Vec3& y, int ignoreA, int ignoreB) const {
  return blockers(x, y, ignoreA, ignoreB).empty();
}

}  // namespace rt::exact
