#include "exact/point_evaluator.h"

#include <cmath>

#include "core/polygon.h"
#include "exact/exact_kernel.h"
#include "exact/exact_reference.h"
#include "exact/geometry_util.h"

namespace rt::exact {
namespace {

// Appends a slot to a pool of polygons that keeps the slots' storage between points.
Polygon& slot(std::vector<Polygon>& pool, std::size_t& count) {
  if (count == pool.size()) pool.emplace_back();
  return pool[count++];
}

}  // namespace

PointEvaluator::PointEvaluator(const PairGeometry& pair, Booleans booleans)
    : pair_(pair), booleans_(booleans) {
  if (pair.sourcePolygon.empty() || pair.receiverPolygon.empty()) return;
  receiver_ = clipToHalfspace(pair.receiverPolygon, pair.sourcePolygon.front(), pair.sourceNormal);
  if (receiver_.size() >= 3) receiverArea_ = polygonArea(receiver_);
  for (const Polygon& polygon : pair.blockers) {
    Occluder occluder{&polygon, Vec3::Zero(), {}, {}};
    const Vec3 n = newellNormal(polygon);
    if (n.norm() > 0) occluder.normal = n.normalized();
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      const Vec3 inward = occluder.normal.cross(polygon[(k + 1) % polygon.size()] - polygon[k]);
      occluder.inward.push_back(inward.norm() > 0 ? Vec3(inward.normalized()) : Vec3::Zero());
    }
    occluder.inFrontOfReceiver =
        clipToHalfspace(polygon, pair.receiverPolygon.front(), pair.receiverNormal);  // beyond it: no shadow
    occluders_.push_back(std::move(occluder));
  }
}

// How one occluder relates to the pyramid from x over the clipped receiver, decided in double precision with
// a margin `eps`; Unknown whenever the margin does not prove Outside or Covers.
PointEvaluator::Relation PointEvaluator::classify(const Occluder& occluder, const Vec3& x, double eps) const {
  const Polygon& polygon = *occluder.polygon;
  for (const Vec3& plane : cone_) {
    double hi = -INFINITY;
    for (const Vec3& v : polygon) hi = std::max(hi, plane.dot(v - x));
    if (hi <= eps) return Relation::Outside;
  }
  if (distanceRange(polygon, pair_.receiverPolygon.front(), pair_.receiverNormal).second <= eps)
    return Relation::Outside;
  const Vec3& n = occluder.normal;
  if (n.isZero()) return Relation::Outside;
  const Vec3& o = polygon.front();
  const double dx = n.dot(x - o);
  const auto [lo, hi] = distanceRange(receiver_, o, n);
  // The occluder's plane does not cut any segment from x to the receiver.
  if ((dx >= eps && lo >= eps) || (dx <= -eps && hi <= -eps)) return Relation::Outside;
  // The plane separates x from the whole receiver: covered when every corner ray pierces the occluder inside.
  const bool separates = (dx > eps && hi < -eps) || (dx < -eps && lo > eps);
  if (!separates) return Relation::Unknown;
  for (const Vec3& c : receiver_) {
    const double dc = n.dot(c - o);
    const Vec3 q = x + (dx / (dx - dc)) * (c - x);
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      if (occluder.inward[k].isZero()) continue;
      if (occluder.inward[k].dot(q - polygon[k]) <= eps) return Relation::Unknown;
    }
  }
  return Relation::Covers;
}

// Receiver pieces minus the shadow of one occluder from x, in double precision: the shadow is the receiver
// plane's intersection with the cone from x over the occluder (clipped to lie between x and the receiver
// plane), so subtracting it means splitting each convex piece by the cone's side planes and dropping the part
// inside all of them. Rounding can only move piece boundaries by ~1e-16 of the scene size; it never drops or
// duplicates an area.
void PointEvaluator::subtractShadow(const Vec3& x, const Occluder& occluder, double eps,
                                    double minArea) const {
  if (occluder.inFrontOfReceiver.size() < 3 || occluder.normal.isZero()) return;
  clipToHalfspace(occluder.inFrontOfReceiver, x, -pair_.receiverNormal, clipped_);  // behind x: no shadow
  const Polygon& o = clipped_;
  if (o.size() < 3) return;
  if (std::abs(occluder.normal.dot(x - o.front())) <= eps) return;  // seen edge-on: no area
  Vec3 centre = Vec3::Zero();
  for (const Vec3& v : o) centre += v;
  centre /= static_cast<double>(o.size());
  cone_.clear();  // reused for the occluder's cone: the receiver's is no longer needed
  for (std::size_t k = 0; k < o.size(); ++k) {
    Vec3 m = (o[k] - x).cross(o[(k + 1) % o.size()] - x);
    const double ml = m.norm();
    if (ml == 0) continue;
    m /= ml;
    if (m.dot(centre - x) < 0) m = -m;
    cone_.push_back(m);
  }
  // A piece on the outer side of one of the cone's planes (touching counts) meets the shadow in no area:
  // it is kept whole. Cut by the planes before that one, it would come back in pieces, and the pieces
  // would multiply with every occluder after.
  auto outsideCone = [&](const Polygon& piece) {
    for (const Vec3& m : cone_) {
      bool outside = true;
      for (const Vec3& v : piece) outside = outside && m.dot(v - x) <= 0;
      if (outside) return true;
    }
    return false;
  };
  std::size_t nextCount = 0;
  for (std::size_t p = 0; p < pieceCount_; ++p) {
    if (outsideCone(work_[p])) {
      std::swap(slot(next_, nextCount), work_[p]);
      continue;
    }
    inside_ = work_[p];
    for (const Vec3& m : cone_) {
      clipToHalfspace(inside_, x, -m, outside_);
      // Slivers from shadow planes that coincide up to rounding (occluders sharing edges) carry no area:
      // dropping them keeps the piece count from growing with every coincident plane.
      if (!outside_.empty() && polygonArea(outside_) > minArea) std::swap(slot(next_, nextCount), outside_);
      clipToHalfspace(inside_, x, m, outside_);
      std::swap(inside_, outside_);
      if (inside_.empty()) break;
    }
  }
  std::swap(work_, next_);
  pieceCount_ = nextCount;
}

double PointEvaluator::unoccluded(const Vec3& x) const {
  if (pair_.receiverNormal.dot(x - pair_.receiverPolygon.front()) <= 0 || receiver_.size() < 3) return 0;
  return std::max(0.0, lambertContourSum(x, pair_.sourceNormal, receiver_));
}

double PointEvaluator::operator()(const Vec3& x) const {
  ++evaluations_;
  if (pair_.receiverNormal.dot(x - pair_.receiverPolygon.front()) <= 0) return 0;
  if (receiver_.size() < 3) return 0;
  if (occluders_.empty()) return std::max(0.0, lambertContourSum(x, pair_.sourceNormal, receiver_));

  const double eps = kGeometricEpsilon * pair_.scale * 10;
  Vec3 centre = Vec3::Zero();
  for (const Vec3& c : receiver_) centre += c;
  centre /= static_cast<double>(receiver_.size());
  cone_.clear();
  for (std::size_t k = 0; k < receiver_.size(); ++k) {
    Vec3 n = (receiver_[k] - x).cross(receiver_[(k + 1) % receiver_.size()] - x);
    const double len = n.norm();
    if (len == 0) continue;
    n /= len;
    if (n.dot(centre - x) < 0) n = -n;
    cone_.push_back(n);
  }
  uncertain_.clear();
  for (const Occluder& occluder : occluders_) {
    switch (classify(occluder, x, eps)) {
      case Relation::Covers:
        return 0;
      case Relation::Outside:
        break;
      case Relation::Unknown:
        uncertain_.push_back(&occluder);
        break;
    }
  }
  if (uncertain_.empty()) return std::max(0.0, lambertContourSum(x, pair_.sourceNormal, receiver_));
  if (booleans_ == Booleans::Exact) {
    ++exactEvaluations_;
    std::vector<Polygon> occluders;
    for (const Occluder* o : uncertain_) occluders.push_back(*o->polygon);
    const detail::ExactVisibility visibility = detail::exactVisibility(
        x, pair_.sourceNormal, pair_.receiverPolygon, pair_.receiverNormal, occluders);
    return pointToRegionFormFactor(x, pair_.sourceNormal, visibility.visible);
  }
  ++splitEvaluations_;
  // x sees the receiver's front (tested above), and the pieces keep its orientation: no facing test per
  // piece.
  pieceCount_ = 0;
  slot(work_, pieceCount_) = receiver_;
  const double minArea = 1e-15 * receiverArea_;
  for (const Occluder* o : uncertain_) {
    subtractShadow(x, *o, eps, minArea);
    if (pieceCount_ == 0) return 0;
  }
  double total = 0;
  for (std::size_t p = 0; p < pieceCount_; ++p) total += lambertContourSum(x, pair_.sourceNormal, work_[p]);
  return std::max(0.0, total);
}

}  // namespace rt::exact
