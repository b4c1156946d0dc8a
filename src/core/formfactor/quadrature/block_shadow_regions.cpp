#include "core/formfactor/quadrature/block_shadow_regions.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/check.h"
#include "core/geometry/plane_clip.h"

namespace rt {
namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The part of the convex polygon `subject` on the left of every edge of the convex polygon `clip` (both
// counter-clockwise): their intersection.
std::vector<Eigen::Vector2d> intersect(std::vector<Eigen::Vector2d> subject, const Eigen::Vector2d* clip,
                                       int clipCount) {
  std::vector<Eigen::Vector2d> next;
  std::vector<double> heights;
  for (int e = 0; e < clipCount && !subject.empty(); ++e) {
    const Eigen::Vector2d &a = clip[e], edge = clip[(e + 1) % clipCount] - clip[e];
    next.clear();
    const std::size_t n = subject.size();
    heights.resize(n);
    for (std::size_t k = 0; k < n; ++k) heights[k] = cross2(edge, subject[k] - a);
    cutByHeights(
        subject.data(), heights.data(), static_cast<int>(n),
        [&](const Eigen::Vector2d& p) { next.push_back(p); }, [](const Eigen::Vector2d&) {});
    subject.swap(next);
    if (subject.size() < 3) subject.clear();
  }
  return subject;
}

}  // namespace

bool BlockShadowRegion::build(const SolidShape& block, const Vec3* from, int fromCount, const Vec3& origin,
                              const Vec3& normal, double eps) {
  umbra_.clear();
  const int corners = static_cast<int>(block.corners.size());
  if (!penumbra_.build(block.corners.data(), corners, from, fromCount, origin, normal, eps)) return false;
  origin_ = origin;
  u_ = normal.unitOrthogonal();
  v_ = normal.cross(u_);
  eps_ = eps;
  // The block's projection from each corner of `from` (penumbra_.build has checked that each is bounded,
  // and refused a block of more corners than its points hold, which has no region), intersected.
  RT_CHECK(corners <= kMaxHullPoints, "a block's region built with more corners than it holds");
  std::array<Eigen::Vector2d, kMaxHullPoints> points, hull;
  for (int r = 0; r < fromCount; ++r) {
    const double hr = normal.dot(from[r] - origin);
    for (int c = 0; c < corners; ++c) {
      const Vec3& corner = block.corners[static_cast<std::size_t>(c)];
      const double hc = normal.dot(corner - origin);
      const Vec3 x = from[r] + (corner - from[r]) * (hr / (hr - hc)) - origin;
      points[static_cast<std::size_t>(c)] = {u_.dot(x), v_.dot(x)};
    }
    const int count = convexHull2d(points.data(), corners, hull.data());
    if (count < 3) {
      umbra_.clear();
      break;
    }
    umbra_ = r == 0 ? std::vector<Eigen::Vector2d>(hull.begin(), hull.begin() + count)
                    : intersect(std::move(umbra_), hull.data(), count);
    if (umbra_.empty()) break;
  }
  return true;
}

bool BlockShadowRegion::hidesAll(const Vec3* polygon, int count) const {
  const std::size_t m = umbra_.size();
  if (m < 3) return false;
  for (int k = 0; k < count; ++k) {
    const Vec3 d = polygon[k] - origin_;
    const Eigen::Vector2d p{u_.dot(d), v_.dot(d)};
    for (std::size_t e = 0; e < m; ++e) {
      const Eigen::Vector2d edge = umbra_[(e + 1) % m] - umbra_[e];
      if (!(cross2(edge, p - umbra_[e]) > eps_ * edge.norm())) return false;
    }
  }
  return true;
}

BlockVerdict RowShadowRegions::judge(int rowElement, const Vec3* rowCorners, int rowCount, int solid,
                                     const Vec3* other, int otherCount, const Vec3& origin,
                                     const Vec3& normal) {
  if (solid < 0 || static_cast<std::size_t>(solid) >= shapes_->size()) return BlockVerdict::Unknown;
  if (rowElement != rowElement_) {
    rowElement_ = rowElement;
    entries_.clear();
  }
  const double offset = normal.dot(origin);
  // The same plane to rounding: the elements of one wall share it up to the mesh's arithmetic.
  Entry* entry = nullptr;
  for (Entry& e : entries_)
    if (e.solid == solid && e.normal.dot(normal) > 1 - 1e-12 && std::abs(e.offset - offset) <= eps_) {
      entry = &e;
      break;
    }
  if (!entry) {
    entry = &entries_.emplace_back();
    entry->solid = solid;
    entry->normal = normal;
    entry->offset = offset;
    entry->bounded = entry->region.build((*shapes_)[static_cast<std::size_t>(solid)], rowCorners, rowCount,
                                         origin, normal, eps_);
  }
  if (!entry->bounded) return BlockVerdict::Unknown;
  if (entry->region.misses(other, otherCount)) return BlockVerdict::Misses;
  if (entry->region.hidesAll(other, otherCount)) return BlockVerdict::HidesAll;
  return BlockVerdict::Shades;
}

ContactShadowRegions::ContactShadowRegions(const std::vector<SolidShape>& shapes, int elementCount,
                                           const std::vector<std::vector<Vec3>>& polygons,
                                           const std::vector<Vec3>& normals, double eps)
    : contactOf_(shapes.size(), -1) {
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    for (const auto& [n, offset] : shapes[s].planes) {
      // Elements in the face's plane, facing the block.
      std::vector<char> onPlane(static_cast<std::size_t>(elementCount), 0);
      bool any = false;
      for (int e = 0; e < elementCount; ++e) {
        if (!(normals[static_cast<std::size_t>(e)].dot(n) < -1 + 1e-9)) continue;
        bool in = true;
        for (const Vec3& v : polygons[static_cast<std::size_t>(e)]) in &= std::abs(n.dot(v) - offset) <= eps;
        onPlane[static_cast<std::size_t>(e)] = in;
        any |= in;
      }
      if (!any) continue;
      Contact& contact = contacts_.emplace_back();
      contact.solid = static_cast<int>(s);
      contact.onPlane = std::move(onPlane);
      contact.regions.resize(static_cast<std::size_t>(elementCount));
      contact.bounded.assign(static_cast<std::size_t>(elementCount), 0);
      const Vec3 origin = n * offset, up = -n;
      for (int e = 0; e < elementCount; ++e) {
        const std::vector<Vec3>& polygon = polygons[static_cast<std::size_t>(e)];
        contact.bounded[static_cast<std::size_t>(e)] = contact.regions[static_cast<std::size_t>(e)].build(
            shapes[s], polygon.data(), static_cast<int>(polygon.size()), origin, up, eps);
      }
      contactOf_[s] = static_cast<int>(contacts_.size()) - 1;
      break;  // one contact plane per block: the one it stands on
    }
  }
}

BlockVerdict ContactShadowRegions::judge(int solid, int standingElement, const Vec3* standing,
                                         int standingCount, int otherElement) const {
  if (solid < 0 || static_cast<std::size_t>(solid) >= contactOf_.size() || contactOf_[solid] < 0)
    return BlockVerdict::Unknown;
  const Contact& contact = contacts_[static_cast<std::size_t>(contactOf_[solid])];
  if (!contact.onPlane[static_cast<std::size_t>(standingElement)] ||
      !contact.bounded[static_cast<std::size_t>(otherElement)])
    return BlockVerdict::Unknown;
  const BlockShadowRegion& region = contact.regions[static_cast<std::size_t>(otherElement)];
  if (region.misses(standing, standingCount)) return BlockVerdict::Misses;
  if (region.hidesAll(standing, standingCount)) return BlockVerdict::HidesAll;
  return BlockVerdict::Shades;
}

}  // namespace rt
