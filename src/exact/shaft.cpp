#include "exact/shaft.h"

#include <algorithm>

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

PairGeometry setUpPair(const Mesh& mesh, int source, int receiver, bool cullOccluders) {
  PairGeometry pair;
  pair.source = source;
  pair.receiver = receiver;
  pair.sourcePolygon = mesh.polygon(source);
  pair.receiverPolygon = mesh.polygon(receiver);
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
  for (std::size_t k = 0; k < mesh.elements.size(); ++k) {
    const int element = static_cast<int>(k);
    if (element == source || element == receiver) continue;
    const Polygon polygon = mesh.polygon(element);
    if (!shaftBox.intersects(boundsOf(polygon))) continue;
    // Behind or in either element's plane: no ray between the fronts passes there.
    if (distanceRange(polygon, si, pair.sourceNormal).second <= eps) continue;
    if (distanceRange(polygon, rj, pair.receiverNormal).second <= eps) continue;
    bool outside = false;
    for (const Plane& plane : planes) {
      double lo = plane.distance(polygon.front());
      for (const Vec3& v : polygon) lo = std::min(lo, plane.distance(v));
      if (lo >= -eps) {
        outside = true;
        break;
      }
    }
    if (outside) continue;
    pair.occluders.push_back(element);
    pair.occluderPolygons.push_back(polygon);
  }
  return pair;
}

std::vector<int> shaftCandidates(const Mesh& mesh, int source, int receiver) {
  return setUpPair(mesh, source, receiver).occluders;
}

}  // namespace rt::exact
