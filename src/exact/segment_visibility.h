// Exact segment visibility V(x, y) (CGAL AABB tree behind a pimpl: this header includes no CGAL).
#pragma once

#include <memory>
#include <vector>

#include "core/mesh.h"

namespace rt::exact {

// V(x, y) for points on mesh elements: CGAL AABB tree over the elements' triangles with exact predicates
// (Exact_predicates_inexact_constructions_kernel). A segment is blocked when it meets a triangle of another
// element at a point other than its end points; touching only at an end point, or lying in a triangle's
// plane, does not block.
class SegmentVisibility {
 public:
  explicit SegmentVisibility(const Mesh& mesh);
  ~SegmentVisibility();
  SegmentVisibility(const SegmentVisibility&) = delete;
  SegmentVisibility& operator=(const SegmentVisibility&) = delete;
  // Elements ignoreA and ignoreB (the ones x and y lie on, -1 for none) never block.
  bool visible(const Vec3& x, const Vec3& y, int ignoreA = -1, int ignoreB = -1) const;
  // Every element whose triangles the open segment meets (sorted, unique).
  std::vector<int> blockers(const Vec3& x, const Vec3& y, int ignoreA = -1, int ignoreB = -1) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rt::exact
