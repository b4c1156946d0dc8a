#include "core/formfactor/quadrature/shadow_overlap.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {
namespace {

// Whether the plane of normal n (any length) has all of p on one side and all of q on the other, with a gap
// of more than 2 eps between them.
bool separates(const Vec3& n, const Vec3* p, int np, const Vec3* q, int nq, double eps) {
  const double length2 = n.squaredNorm();
  if (!(length2 > 0)) return false;
  double pLow = std::numeric_limits<double>::infinity(), pHigh = -pLow, qLow = pLow, qHigh = -pLow;
  for (int k = 0; k < np; ++k) {
    const double d = n.dot(p[k]);
    pLow = std::min(pLow, d), pHigh = std::max(pHigh, d);
  }
  for (int k = 0; k < nq; ++k) {
    const double d = n.dot(q[k]);
    qLow = std::min(qLow, d), qHigh = std::max(qHigh, d);
    if (qLow <= pHigh && qHigh >= pLow) return false;  // overlapping already: no gap along n
  }
  const double gap = std::max(qLow - pHigh, pLow - qHigh);
  return gap > 0 && gap * gap > 4 * eps * eps * length2;
}

}  // namespace

bool hullsSeparated(const Vec3* p, int np, const std::vector<std::pair<int, int>>& pEdges, const Vec3* q,
                    int nq, const std::vector<std::pair<int, int>>& qEdges, const std::vector<Vec3>& qNormals,
                    double eps) {
  // The cheapest candidates first: q's faces, then p's (an edge and a point), then edge against edge.
  for (const Vec3& n : qNormals)
    if (separates(n, p, np, q, nq, eps)) return true;
  for (const auto& [a, b] : pEdges) {
    const Vec3 edge = p[b] - p[a];
    for (int k = 0; k < np; ++k)
      if (k != a && k != b && separates(edge.cross(p[k] - p[a]), p, np, q, nq, eps)) return true;
  }
  for (const auto& [a, b] : pEdges) {
    const Vec3 edge = p[b] - p[a];
    for (const auto& [c, d] : qEdges)
      if (separates(edge.cross(q[d] - q[c]), p, np, q, nq, eps)) return true;
  }
  return false;
}

bool solidOutsideHullOfSolidAndPolygon(const SolidShape& other, const SolidShape& near, const Vec3* polygon,
                                       int count, double eps) {
  if (count < 3) return false;
  // The hull's points, and every edge it can have: the solid's own, the polygon's, and each corner of one
  // joined to each corner of the other.
  std::vector<Vec3> points = near.corners;
  const int n = static_cast<int>(points.size());
  points.insert(points.end(), polygon, polygon + count);
  std::vector<std::pair<int, int>> edges, otherEdges;
  for (const SolidShape::Edge& e : near.edges) edges.push_back({e.a, e.b});
  for (int k = 0; k < count; ++k) edges.push_back({n + k, n + (k + 1) % count});
  for (int c = 0; c < n; ++c)
    for (int k = 0; k < count; ++k) edges.push_back({c, n + k});
  for (const SolidShape::Edge& e : other.edges) otherEdges.push_back({e.a, e.b});
  std::vector<Vec3> normals;
  for (const auto& [normal, offset] : other.planes) normals.push_back(normal);
  return hullsSeparated(points.data(), static_cast<int>(points.size()), edges, other.corners.data(),
                        static_cast<int>(other.corners.size()), otherEdges, normals, eps);
}

}  // namespace rt
