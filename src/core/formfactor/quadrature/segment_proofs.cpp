#include "core/formfactor/quadrature/segment_proofs.h"

#include <algorithm>
#include <cmath>

#include "core/formfactor/quadrature/shadow_clipper_detail.h"
#include "core/geometry/segment_clip.h"

namespace rt {

bool polygonCutsEverySegment(const Vec3* from, int fromCount, const Vec3* to, int toCount,
                             const Vec3* polygon, int count, const Vec3& normal, double offset, double eps) {
  if (fromCount < 1 || toCount < 1 || count < 3) return false;
  auto height = [&](const Vec3& p) { return normal.dot(p) - offset; };
  const double side = height(to[0]);
  for (int k = 0; k < toCount; ++k)
    if (!(height(to[k]) * side > 0 && std::abs(height(to[k])) > eps)) return false;
  for (int k = 0; k < fromCount; ++k)
    if (!(height(from[k]) * side < 0 && std::abs(height(from[k])) > eps)) return false;
  for (int f = 0; f < fromCount; ++f)
    for (int t = 0; t < toCount; ++t) {
      const double hf = height(from[f]), ht = height(to[t]);
      const Vec3 crossing = from[f] + (to[t] - from[f]) * (hf / (hf - ht));
      for (int k = 0; k < count; ++k) {
        const Vec3 edge = polygon[(k + 1) % count] - polygon[k];
        if (!(edge.cross(crossing - polygon[k]).dot(normal) > eps * edge.norm())) return false;
      }
    }
  return true;
}

bool solidMissesEverySegment(const Vec3* from, int fromCount, const Vec3* to, int toCount,
                             const SolidPlanes& solid, double eps) {
  for (const auto& [n, offset] : solid) {
    bool front = true;
    for (int k = 0; k < fromCount && front; ++k) front = n.dot(from[k]) - offset > eps;
    for (int k = 0; k < toCount && front; ++k) front = n.dot(to[k]) - offset > eps;
    if (front) return true;
  }
  return false;
}

bool segmentEntersSolid(const Vec3& p, const Vec3& q, const SolidPlanes& solid, double eps) {
  double t0 = 0, t1 = 1;
  const Vec3 d = q - p;
  for (const auto& [n, offset] : solid) {
    // Inside where start + rate t < 0 (outward normals): the open half-space -start - rate t > 0, and a
    // segment parallel to a face inside only strictly below it.
    const double start = n.dot(p) - offset + eps, rate = n.dot(d);
    if (!clipRange(-start, -rate, 0.0, Boundary::Open, t0, t1)) return false;
  }
  return true;
}

bool solidOutsideHullOf(const Vec3* a, int na, const Vec3* b, int nb, const Vec3* corners, int cornerCount,
                        double eps) {
  if (na < 3 || nb < 3 || cornerCount < 1) return false;
  // All of the edge's polygon lies on its centre's side of each plane; the solid's corners are tested first,
  // as most planes have some on that side.
  auto separates = [&](const Vec3* edges, int ne, const Vec3* others, int no) {
    const Vec3 centre = cornerMean(edges, ne);
    return shadow_detail::forEachEdgeCornerPlane(
        edges, ne, others, no, eps, [&](const Vec3& p, Vec3 n, double margin2) {
          auto beyond = [&](double d) { return d > 0 && d * d > margin2; };
          const double side = n.dot(centre - p);
          if (side * side <= margin2) return false;  // the polygon edge-on to it: no side to hold
          if (side > 0) n = -n;                      // the polygons behind n, the solid to be wholly in front
          bool apart = true;
          for (int c = 0; c < cornerCount && apart; ++c) apart = beyond(n.dot(corners[c] - p));
          for (int j = 0; j < no && apart; ++j) apart = !beyond(n.dot(others[j] - p));
          return apart;
        });
  };
  return separates(a, na, b, nb) || separates(b, nb, a, na);
}

bool solidCutsEverySegment(const Vec3* from, int fromCount, const Vec3* to, int toCount,
                           const SolidPlanes& solid, const Vec3& centre, double eps) {
  if (fromCount < 1 || toCount < 1) return false;
  Vec3 fromCentre = Vec3::Zero(), toCentre = Vec3::Zero();
  for (int p = 0; p < fromCount; ++p) fromCentre += from[p];
  for (int p = 0; p < toCount; ++p) toCentre += to[p];
  const Vec3 sight = (toCentre / toCount - fromCentre / fromCount).normalized();
  SmallBuffer<double, ConvexPolygon::kInline> heights;
  heights.reserve(toCount);
  for (std::size_t plane = 0; plane <= solid.size(); ++plane) {
    const Vec3 normal = plane == 0 ? sight : solid[plane - 1].first;
    const double offset = normal.dot(centre);
    // `to` strictly on one side of the plane, `from` strictly on the other.
    double sign = 0;
    bool separated = true;
    for (int k = 0; k < toCount && separated; ++k) {
      heights[k] = normal.dot(to[k]) - offset;
      separated = std::abs(heights[k]) > eps && !(sign != 0 && heights[k] * sign < 0);
      sign = heights[k];
    }
    // Each crossing strictly inside every face plane, the first one outside ending this cross-section.
    bool inside = separated;
    for (int p = 0; p < fromCount && inside; ++p) {
      const double h = normal.dot(from[p]) - offset;
      inside = h * sign < 0 && std::abs(h) > eps;
      for (int k = 0; k < toCount && inside; ++k) {
        const Vec3 crossing = from[p] + (to[k] - from[p]) * (h / (h - heights[k]));
        for (const auto& [n, faceOffset] : solid)
          if (!(n.dot(crossing) - faceOffset < -eps)) {
            inside = false;
            break;
          }
      }
    }
    if (inside) return true;
  }
  return false;
}

}  // namespace rt
