#include "exact/point_evaluator.h"

#include <cmath>

#include "core/polygon.h"
#include "exact/exact_kernel.h"
#include "exact/exact_reference.h"
#include "exact/geometry_util.h"

namespace rt::exact {
namespace {

struct ConePlane {
  Vec3 normal;  // unit, pointing into the pyramid
  double distance(const Vec3& p, const Vec3& apex) const { return normal.dot(p - apex); }
};

enum class Relation { Outside, Covers, Unknown };

// How one occluder relates to the pyramid from x over the clipped receiver `rc`, decided in double precision
// with a margin `eps`; Unknown whenever the margin does not prove Outside or Covers.
Relation classify(const Polygon& occluder, const Vec3& x, const Polygon& rc,
                  const std::vector<ConePlane>& cone, const Vec3& receiverPoint, const Vec3& receiverNormal,
                  double eps) {
  for (const ConePlane& plane : cone) {
    double hi = -INFINITY;
    for (const Vec3& v : occluder) hi = std::max(hi, plane.distance(v, x));
    if (hi <= eps) return Relation::Outside;
  }
  if (distanceRange(occluder, receiverPoint, receiverNormal).second <= eps) return Relation::Outside;

  Vec3 n = newellNormal(occluder);
  const double len = n.norm();
  if (len == 0) return Relation::Outside;
  n /= len;
  const Vec3& o = occluder.front();
  const double dx = n.dot(x - o);
  const auto [lo, hi] = distanceRange(rc, o, n);
  // The occluder's plane does not cut any segment from x to the receiver.
  if ((dx >= eps && lo >= eps) || (dx <= -eps && hi <= -eps)) return Relation::Outside;
  // The plane separates x from the whole receiver: covered when every corner ray pierces the occluder inside.
  const bool separates = (dx > eps && hi < -eps) || (dx < -eps && lo > eps);
  if (!separates) return Relation::Unknown;
  const std::size_t m = occluder.size();
  for (const Vec3& c : rc) {
    const double dc = n.dot(c - o);
    const Vec3 q = x + (dx / (dx - dc)) * (c - x);
    for (std::size_t k = 0; k < m; ++k) {
      const Vec3& a = occluder[k];
      const Vec3& b = occluder[(k + 1) % m];
      Vec3 inward = n.cross(b - a);
      const double el = inward.norm();
      if (el == 0) continue;
      inward /= el;
      if (inward.dot(q - a) <= eps) return Relation::Unknown;
    }
  }
  return Relation::Covers;
}

// Receiver pieces minus the shadow of one occluder from x, in double precision: the shadow is the receiver
// plane's intersection with the cone from x over the occluder (clipped to lie between x and the receiver
// plane), so subtracting it means splitting each convex piece by the cone's side planes and dropping the part
// inside all of them. Rounding can only move piece boundaries by ~1e-16 of the scene size; it never drops or
// duplicates an area.
void subtractShadow(const Vec3& x, const Polygon& occluder, const Vec3& receiverPoint,
                    const Vec3& receiverNormal, double eps, double minArea, std::vector<Polygon>& pieces) {
  Polygon o =
      clipToHalfspace(occluder, receiverPoint, receiverNormal);  // beyond the receiver plane: no shadow
  if (o.size() < 3) return;
  o = clipToHalfspace(o, x, -receiverNormal);  // farther from the receiver plane than x: behind x
  if (o.size() < 3) return;
  Vec3 on = newellNormal(o);
  const double len = on.norm();
  if (len == 0) return;
  on /= len;
  if (std::abs(on.dot(x - o.front())) <= eps) return;  // seen edge-on: no area
  Vec3 centre = Vec3::Zero();
  for (const Vec3& v : o) centre += v;
  centre /= static_cast<double>(o.size());
  std::vector<Vec3> sides;
  for (std::size_t k = 0; k < o.size(); ++k) {
    Vec3 m = (o[k] - x).cross(o[(k + 1) % o.size()] - x);
    const double ml = m.norm();
    if (ml == 0) continue;
    m /= ml;
    if (m.dot(centre - x) < 0) m = -m;
    sides.push_back(m);
  }
  std::vector<Polygon> result;
  for (const Polygon& piece : pieces) {
    Polygon inside = piece;
    for (const Vec3& m : sides) {
      Polygon outside = clipToHalfspace(inside, x, -m);
      // Slivers from shadow planes that coincide up to rounding (occluders sharing edges) carry no area:
      // dropping them keeps the piece count from growing with every coincident plane.
      if (!outside.empty() && polygonArea(outside) > minArea) result.push_back(std::move(outside));
      inside = clipToHalfspace(inside, x, m);
      if (inside.empty()) break;
    }
  }
  pieces = std::move(result);
}

}  // namespace

double PointEvaluator::operator()(const Vec3& x) const {
  ++evaluations_;
  const Vec3& r0 = pair_.receiverPolygon.front();
  if (pair_.receiverNormal.dot(x - r0) <= 0) return 0;
  const Polygon rc = clipToHalfspace(pair_.receiverPolygon, x, pair_.sourceNormal);
  if (rc.size() < 3) return 0;
  if (pair_.occluderPolygons.empty()) return pointToPolygonFormFactor(x, pair_.sourceNormal, rc);

  const double eps = kGeometricEpsilon * pair_.scale * 10;
  Vec3 centre = Vec3::Zero();
  for (const Vec3& c : rc) centre += c;
  centre /= static_cast<double>(rc.size());
  std::vector<ConePlane> cone;
  for (std::size_t k = 0; k < rc.size(); ++k) {
    Vec3 n = (rc[k] - x).cross(rc[(k + 1) % rc.size()] - x);
    const double len = n.norm();
    if (len == 0) continue;
    n /= len;
    if (n.dot(centre - x) < 0) n = -n;
    cone.push_back({n});
  }
  std::vector<const Polygon*> uncertain;
  for (const Polygon& occluder : pair_.occluderPolygons) {
    switch (classify(occluder, x, rc, cone, r0, pair_.receiverNormal, eps)) {
      case Relation::Covers:
        return 0;
      case Relation::Outside:
        break;
      case Relation::Unknown:
        uncertain.push_back(&occluder);
        break;
    }
  }
  if (uncertain.empty()) return pointToPolygonFormFactor(x, pair_.sourceNormal, rc);
  if (booleans_ == Booleans::Exact) {
    ++exactEvaluations_;
    std::vector<Polygon> occluders;
    for (const Polygon* o : uncertain) occluders.push_back(*o);
    const detail::ExactVisibility visibility = detail::exactVisibility(
        x, pair_.sourceNormal, pair_.receiverPolygon, pair_.receiverNormal, occluders);
    return pointToRegionFormFactor(x, pair_.sourceNormal, visibility.visible);
  }
  ++splitEvaluations_;
  std::vector<Polygon> pieces{rc};
  const double minArea = 1e-15 * polygonArea(rc);
  for (const Polygon* o : uncertain) {
    subtractShadow(x, *o, r0, pair_.receiverNormal, eps, minArea, pieces);
    if (pieces.empty()) return 0;
  }
  double total = 0;
  for (const Polygon& piece : pieces) total += pointToPolygonFormFactor(x, pair_.sourceNormal, piece);
  return total;
}

}  // namespace rt::exact
