// Where on the source's plane a convex solid can hide any part of a receiver.
//
// A point x of the plane is shaded from receiver point r by the solid when the segment from x to r meets
// it, that is when x is r's central projection of some point of the solid. With every corner of the solid
// strictly between the plane and every corner of the receiver, both projections involved (from a fixed r,
// of the solid; through a fixed solid point, of the receiver) are projective maps that keep convex sets
// convex, so every such x lies in the convex hull of the projections of the solid's corners from the
// receiver's corners. A source panel outside that hull sees all of the receiver past this solid.
//
// The test is as tight as the shaded region is (it is that region when the region is convex) and costs a
// few 2D cross products per panel, where the hull of the panel and the receiver (shadow_clipper.h) costs a
// few dozen 3D planes.
#pragma once

#include <Eigen/Core>
#include <array>

#include "core/vec.h"

namespace rt {

// The convex hull of up to kMaxHullPoints points (reordered), counter-clockwise into `out` (room for as
// many); returns its corner count, 0 when it has fewer than three.
constexpr int kMaxHullPoints = 64;
int convexHull2d(Eigen::Vector2d* points, int n, Eigen::Vector2d* out);

class PenumbraRegion {
 public:
  // `corners`: the solid's; `receiver`: the receiver's corners; the plane through `origin` with unit
  // `normal`, the receiver in front of it. False (and no region) when some corner of the solid lies behind
  // the plane or not strictly below some receiver corner (the region is unbounded then), or when there are
  // more than 64 projections.
  bool build(const Vec3* corners, int cornerCount, const Vec3* receiver, int receiverCount,
             const Vec3& origin, const Vec3& normal, double eps);
  // False only when the convex polygon, lying in the plane, is wholly outside the region by more than eps
  // (a length): no point of it is shaded by the solid.
  bool meets(const Vec3* polygon, int count) const;

 private:
  Vec3 origin_ = Vec3::Zero(), u_ = Vec3::Zero(), v_ = Vec3::Zero();
  double eps_ = 0;
  // Counter-clockwise about the plane's normal. Fixed room: one region is made for every occluded pair, and
  // the heap would cost more than the hull.
  static constexpr int kMaxPoints = 64;
  std::array<Eigen::Vector2d, kMaxPoints> hull_;
  std::array<double, kMaxPoints> margin2_;  // (eps times each hull edge's length) squared, for meets()
  int count_ = 0;
};

}  // namespace rt
