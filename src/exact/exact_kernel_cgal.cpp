// Exact visibility from a point with CGAL: clipping and central projection templated over the kernel (exact
// or floating constructions, CGAL style), 2D Boolean set operations with the exact constructions kernel. This
// is one of the two translation units of the library that include CGAL; keep everything that changes often
// elsewhere.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <list>

#include "exact/exact_kernel.h"

namespace rt::exact::detail {
namespace {

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FloatingKernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// The receiver's plane is parametrised by dropping the coordinate along which its normal is largest: an
// affine map with rational coefficients, so exact points stay exact. 2D (u, v) = (coordinate a1, coordinate
// a2) with a1, a2 cyclic after the dropped axis, so 2D counter-clockwise means counter-clockwise seen from
// +axis.
struct PlaneChart {
  int axis = 2, a1 = 0, a2 = 1;
  bool flipped =
      false;  // receiver normal points along -axis: 2D CCW is clockwise seen from the receiver's front
  Vec3 normal;
  double offset = 0;  // plane normal . p = offset (double, for lifting results back to 3D)

  PlaneChart(const Vec3& n, const Vec3& onPlane) : normal(n), offset(n.dot(onPlane)) {
    n.cwiseAbs().maxCoeff(&axis);
    a1 = (axis + 1) % 3;
    a2 = (axis + 2) % 3;
    flipped = n[axis] < 0;
  }
  Vec3 lift(double u, double v) const {
    Vec3 p;
    p[a1] = u;
    p[a2] = v;
    p[axis] = (offset - normal[a1] * u - normal[a2] * v) / normal[axis];
    return p;
  }
};

template <class K>
class Projector {
 public:
  using FT = typename K::FT;
  using Point2 = typename K::Point_2;
  using Polygon2 = CGAL::Polygon_2<K>;
  struct P3 {
    FT c[3];
  };
  // Closed half-space a.p + d >= 0.
  struct Halfspace {
    FT a[3];
    FT d;
    FT side(const P3& p) const { return a[0] * p.c[0] + a[1] * p.c[1] + a[2] * p.c[2] + d; }
  };

  Projector(const Vec3& x, const Vec3& sourceNormal, const Polygon& receiver, const Vec3& receiverNormal)
      : chart_(receiverNormal, receiver.front()), x_(toP3(x)) {
    receiverPlane_ = halfspace(receiverNormal, receiver.front());
    const Halfspace sourceFront = halfspace(sourceNormal, x);
    xDistance_ = receiverPlane_.side(x_);
    if (CGAL::sign(xDistance_) != CGAL::POSITIVE)
      return;  // x behind or in the receiver's plane: sees its back
    std::vector<P3> r;
    for (const Vec3& v : receiver) r.push_back(toP3(v));
    clipped_ = clip(r, sourceFront);
    receiver2d_ = toPolygon2(clipped_);
    if (receiver2d_.size() < 3) return;
    const CGAL::Orientation o = receiver2d_.orientation();
    if (o == CGAL::COLLINEAR) return;
    if (o == CGAL::CLOCKWISE) receiver2d_.reverse_orientation();
    faces_ = true;
    buildCone();
  }

  bool faces() const { return faces_; }
  const Polygon2& receiver2d() const { return receiver2d_; }

  // The projection of one occluder, empty when it does not cover any area of the receiver's plane inside the
  // pyramid.
  Polygon2 project(const Polygon& occluder) const {
    std::vector<P3> o;
    for (const Vec3& v : occluder) o.push_back(toP3(v));
    o = clip(o, receiverPlane_);  // beyond the receiver's plane: blocks nothing
    for (const Halfspace& h : cone_) {
      if (o.size() < 3) return {};
      o = clip(o, h);
    }
    if (o.size() < 3) return {};
    std::vector<P3> projected;
    for (const P3& p : o) {
      // Inside the pyramid only x itself lies at x's distance from the receiver plane; an occluder through x
      // is seen edge-on and covers nothing.
      const FT dp = receiverPlane_.side(p);
      if (dp == xDistance_) return {};
      const FT t = xDistance_ / (xDistance_ - dp);
      projected.push_back({{x_.c[0] + (p.c[0] - x_.c[0]) * t, x_.c[1] + (p.c[1] - x_.c[1]) * t,
                            x_.c[2] + (p.c[2] - x_.c[2]) * t}});
    }
    Polygon2 poly = toPolygon2(projected);
    if (poly.size() < 3) return {};
    const CGAL::Orientation orientation = poly.orientation();
    if (orientation == CGAL::COLLINEAR) return {};
    if (orientation == CGAL::CLOCKWISE) poly.reverse_orientation();
    return poly;
  }

  // Back to 3D doubles on the receiver's plane, CCW seen from the receiver's front (clockwise when `hole`).
  Polygon toWorld(const Polygon2& poly, bool hole) const {
    Polygon out;
    for (auto it = poly.vertices_begin(); it != poly.vertices_end(); ++it)
      out.push_back(chart_.lift(CGAL::to_double(it->x()), CGAL::to_double(it->y())));
    const bool ccwIn2d = poly.orientation() != CGAL::CLOCKWISE;
    const bool ccwSeenFromFront = ccwIn2d != chart_.flipped;
    if (ccwSeenFromFront == hole) std::reverse(out.begin(), out.end());
    return out;
  }

  Polygon clippedReceiverWorld() const {
    Polygon out;
    for (const P3& p : clipped_)
      out.push_back(Vec3(CGAL::to_double(p.c[0]), CGAL::to_double(p.c[1]), CGAL::to_double(p.c[2])));
    return out;
  }

 private:
  static P3 toP3(const Vec3& v) { return {{FT(v.x()), FT(v.y()), FT(v.z())}}; }

  static Halfspace halfspace(const Vec3& normal, const Vec3& through) {
    Halfspace h{{FT(normal.x()), FT(normal.y()), FT(normal.z())}, FT(0)};
    h.d = -(h.a[0] * FT(through.x()) + h.a[1] * FT(through.y()) + h.a[2] * FT(through.z()));
    return h;
  }

  // Sutherland-Hodgman against one closed half-space (points on the plane are kept).
  static std::vector<P3> clip(const std::vector<P3>& polygon, const Halfspace& h) {
    std::vector<P3> out;
    const std::size_t n = polygon.size();
    if (n == 0) return out;
    std::vector<FT> s(n);
    std::vector<CGAL::Sign> sign(n);
    bool allInside = true;
    for (std::size_t k = 0; k < n; ++k) {
      s[k] = h.side(polygon[k]);
      sign[k] = CGAL::sign(s[k]);
      allInside = allInside && sign[k] != CGAL::NEGATIVE;
    }
    if (allInside) return polygon;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t l = (k + 1) % n;
      if (sign[k] != CGAL::NEGATIVE) out.push_back(polygon[k]);
      if ((sign[k] == CGAL::POSITIVE && sign[l] == CGAL::NEGATIVE) ||
          (sign[k] == CGAL::NEGATIVE && sign[l] == CGAL::POSITIVE)) {
        const FT t = s[k] / (s[k] - s[l]);
        const P3& a = polygon[k];
        const P3& b = polygon[l];
        out.push_back({{a.c[0] + (b.c[0] - a.c[0]) * t, a.c[1] + (b.c[1] - a.c[1]) * t,
                        a.c[2] + (b.c[2] - a.c[2]) * t}});
      }
    }
    return out;
  }

  // Drops a coordinate; removes repeated and collinear vertices so the result is a valid CGAL polygon.
  Polygon2 toPolygon2(const std::vector<P3>& polygon) const {
    std::vector<Point2> pts;
    for (const P3& p : polygon) {
      Point2 q(p.c[chart_.a1], p.c[chart_.a2]);
      if (pts.empty() || pts.back() != q) pts.push_back(q);
    }
    while (pts.size() > 1 && pts.front() == pts.back()) pts.pop_back();
    bool removed = true;
    while (removed && pts.size() >= 3) {
      removed = false;
      for (std::size_t k = 0; k < pts.size() && pts.size() >= 3; ++k) {
        const Point2& prev = pts[(k + pts.size() - 1) % pts.size()];
        const Point2& next = pts[(k + 1) % pts.size()];
        if (CGAL::collinear(prev, pts[k], next)) {
          pts.erase(pts.begin() + static_cast<long>(k));
          removed = true;
        }
      }
    }
    if (pts.size() < 3) return {};
    return Polygon2(pts.begin(), pts.end());
  }

  // Planes through x and each edge of the clipped receiver, oriented towards it: their intersection is the
  // pyramid of rays from x to the receiver (one nappe only, because the receiver is convex and x is not in
  // its plane).
  void buildCone() {
    const std::size_t n = clipped_.size();
    for (std::size_t k = 0; k < n; ++k) {
      const P3& a = clipped_[k];
      const P3& b = clipped_[(k + 1) % n];
      const FT u[3] = {a.c[0] - x_.c[0], a.c[1] - x_.c[1], a.c[2] - x_.c[2]};
      const FT v[3] = {b.c[0] - x_.c[0], b.c[1] - x_.c[1], b.c[2] - x_.c[2]};
      Halfspace h{{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}, FT(0)};
      h.d = -(h.a[0] * x_.c[0] + h.a[1] * x_.c[1] + h.a[2] * x_.c[2]);
      // Orient by the receiver vertex farthest from the plane, never by the edge's own end points: with
      // floating constructions their sides are rounding noise.
      CGAL::Sign orientation = CGAL::ZERO;
      FT farthest(0);
      for (std::size_t m = 0; m < n; ++m) {
        if (m == k || m == (k + 1) % n) continue;
        const FT side = h.side(clipped_[m]);
        const FT magnitude = CGAL::abs(side);
        if (magnitude > farthest) {
          farthest = magnitude;
          orientation = CGAL::sign(side);
        }
      }
      if (orientation == CGAL::ZERO) continue;  // repeated vertex: no plane
      if (orientation == CGAL::NEGATIVE) h = Halfspace{{-h.a[0], -h.a[1], -h.a[2]}, -h.d};
      cone_.push_back(h);
    }
  }

  PlaneChart chart_;
  P3 x_;
  Halfspace receiverPlane_;
  FT xDistance_;
  bool faces_ = false;
  std::vector<P3> clipped_;
  Polygon2 receiver2d_;
  std::vector<Halfspace> cone_;
};

template <class K>
ProjectionResult projectWith(const Projector<K>& projector, const std::vector<Polygon>& occluders,
                             std::vector<CGAL::Polygon_2<K>>* projections2d) {
  ProjectionResult result;
  result.receiverFacesPoint = projector.faces();
  if (!projector.faces()) return result;
  result.clippedReceiver = projector.toWorld(projector.receiver2d(), false);
  for (std::size_t k = 0; k < occluders.size(); ++k) {
    CGAL::Polygon_2<K> p = projector.project(occluders[k]);
    if (p.size() < 3) continue;
    result.projections.push_back(projector.toWorld(p, false));
    result.projectionOwners.push_back(static_cast<int>(k));
    if (projections2d) projections2d->push_back(std::move(p));
  }
  return result;
}

}  // namespace

ProjectionResult projectOccluders(const Vec3& x, const Vec3& sourceNormal, const Polygon& receiver,
                                  const Vec3& receiverNormal, const std::vector<Polygon>& occluders,
                                  Arithmetic arithmetic) {
  if (receiver.size() < 3) return {};
  if (arithmetic == Arithmetic::Exact)
    return projectWith<ExactKernel>(Projector<ExactKernel>(x, sourceNormal, receiver, receiverNormal),
                                    occluders, nullptr);
  return projectWith<FloatingKernel>(Projector<FloatingKernel>(x, sourceNormal, receiver, receiverNormal),
                                     occluders, nullptr);
}

ExactVisibility exactVisibility(const Vec3& x, const Vec3& sourceNormal, const Polygon& receiver,
                                const Vec3& receiverNormal, const std::vector<Polygon>& occluders) {
  using Polygon2 = CGAL::Polygon_2<ExactKernel>;
  using PolygonWithHoles2 = CGAL::Polygon_with_holes_2<ExactKernel>;
  ExactVisibility result;
  if (receiver.size() < 3) return result;
  std::vector<Polygon2> projections;
  const Projector<ExactKernel> projector(x, sourceNormal, receiver, receiverNormal);
  result.projection = projectWith(projector, occluders, &projections);
  if (!result.projection.receiverFacesPoint) return result;
  if (projections.empty()) {
    result.visible.push_back({result.projection.clippedReceiver, {}});
    return result;
  }
  CGAL::Polygon_set_2<ExactKernel> shadow;
  shadow.join(projections.begin(), projections.end());
  CGAL::Polygon_set_2<ExactKernel> visible(projector.receiver2d());
  visible.difference(shadow);
  std::list<PolygonWithHoles2> pieces;
  visible.polygons_with_holes(std::back_inserter(pieces));
  for (const PolygonWithHoles2& piece : pieces) {
    PolygonWithHoles region;
    region.outer = projector.toWorld(piece.outer_boundary(), false);
    for (auto hole = piece.holes_begin(); hole != piece.holes_end(); ++hole)
      region.holes.push_back(projector.toWorld(*hole, true));
    result.visible.push_back(std::move(region));
  }
  return result;
}

}  // namespace rt::exact::detail
