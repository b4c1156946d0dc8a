#include "exact/shaft.h"

#include <algorithm>

#include "exact/blockers.h"
#include "exact/exact_reference.h"
#include "exact/geometry_util.h"

namespace rt::exact {
namespace {

struct Plane {
  Vec3 normal;  // unit; the shaft is on the non-positive side
  double offset;
  double distance(const Vec3& p) const { return normal.dot(p) - offset; }
};

// Hull planes through an edge of `a` and a vertex of `b` with every vertex of both on one side (<= eps).
void addHullPlanes(const Polygon& a, const Polygon& b, double eps, std::vector<Plane>& planes) {
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Vec3& p = a[k];
    const Vec3& q = a[(k + 1) % a.size()];
    for (const Vec3& r : b) {
      Vec3 n = (q - p).cross(r - p);
      const double len = n.norm();
      if (len <= eps * (q - p).norm()) continue;
      n /= len;
      Plane plane{n, n.dot(p)};
      double lo = 0, hi = 0;
      for (const Polygon* poly : {&a, &b})
        for (const Vec3& v : *poly) {
          lo = std::min(lo, plane.distance(v));
          hi = std::max(hi, plane.distance(v));
        }
      if (hi <= eps) {
        planes.push_back(plane);
      } else if (lo >= -eps) {
        planes.push_back({-plane.normal, -plane.offset});
      }
    }
  }
}

}  // namespace

ElementIndex::ElementIndex(const Mesh& mesh) {
  polygons_.reserve(mesh.size());
  boxes_.reserve(mesh.size());
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    polygons_.push_back(mesh.polygon(static_cast<int>(e)));
    boxes_.push_back(boundsOf(polygons_.back()));
  }
  tree_ = BoxTree(boxes_);
}

PairGeometry setUpPair(const Mesh& mesh, int source, int receiver, bool cullOccluders,
                       const ElementIndex* index) {
  PairGeometry pair;
  pair.source = source;
  pair.receiver = receiver;
  pair.sourcePolygon = index ? index->polygon(source) : mesh.polygon(source);
  pair.receiverPolygon = index ? index->polygon(receiver) : mesh.polygon(receiver);
  pair.sourceNormal = mesh.elements[source].normal.normalized();
  pair.receiverNormal = mesh.elements[receiver].normal.normalized();
  Eigen::AlignedBox3d box = boundsOf(pair.sourcePolygon);
  box.extend(boundsOf(pair.receiverPolygon));
  pair.scale = std::max(box.diagonal().norm(), 1e-300);
  const double eps = kGeometricEpsilon * pair.scale;

  // Facing: each element has a vertex strictly in front of the other's plane.
  const Vec3& si = pair.sourcePolygon.front();
  const Vec3& rj = pair.receiverPolygon.front();
  const auto [jLo, jHi] = distanceRange(pair.receiverPolygon, si, pair.sourceNormal);
  const auto [iLo, iHi] = distanceRange(pair.sourcePolygon, rj, pair.receiverNormal);
  (void)jLo;
  (void)iLo;
  pair.facing = jHi > eps && iHi > eps;
  if (!pair.facing) return pair;
  pair.integrationDomain = clipToHalfspace(pair.sourcePolygon, rj, pair.receiverNormal);
  if (pair.integrationDomain.size() < 3) {
    pair.facing = false;
    return pair;
  }
  if (!cullOccluders) return pair;

  std::vector<Plane> planes;
  addHullPlanes(pair.sourcePolygon, pair.receiverPolygon, eps, planes);
  addHullPlanes(pair.receiverPolygon, pair.sourcePolygon, eps, planes);
  const Eigen::AlignedBox3d shaftBox(box.min() - Vec3::Constant(eps), box.max() + Vec3::Constant(eps));
  // The tests in order of cost; `polygon` is the element's.
  auto mayBlock = [&](int element, const Polygon& polygon) {
    if (element == source || element == receiver) return false;
    // Behind or in either element's plane: no ray between the fronts passes there.
    if (distanceRange(polygon, si, pair.sourceNormal).second <= eps) return false;
    if (distanceRange(polygon, rj, pair.receiverNormal).second <= eps) return false;
    for (const Plane& plane : planes) {
      double lo = plane.distance(polygon.front());
      for (const Vec3& v : polygon) lo = std::min(lo, plane.distance(v));
      if (lo >= -eps) return false;
    }
    return true;
  };
  if (index) {
    index->overlapping(shaftBox, pair.occluders,
                       [&](int element) { return mayBlock(element, index->polygon(element)); });
    for (int element : pair.occluders) pair.occluderPolygons.push_back(index->polygon(element));
    pair.blockers = mergeOccluders(mesh, pair.occluders, pair.occluderPolygons, eps);
    return pair;
  }
  for (std::size_t k = 0; k < mesh.elements.size(); ++k) {
    const int element = static_cast<int>(k);
    Polygon polygon = mesh.polygon(element);
    if (!shaftBox.intersects(boundsOf(polygon)) || !mayBlock(element, polygon)) continue;
    pair.occluders.push_back(element);
    pair.occluderPolygons.push_back(std::move(polygon));
  }
  pair.blockers = mergeOccluders(mesh, pair.occluders, pair.occluderPolygons, eps);
  return pair;
}

std::vector<int> shaftCandidates(const Mesh& mesh, int source, int receiver) {
  return setUpPair(mesh, source, receiver).occluders;
}

}  // namespace rt::exact
