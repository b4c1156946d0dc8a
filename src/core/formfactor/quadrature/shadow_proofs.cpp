// ShadowClipper's proofs and probes: whether occluders hide the whole receiver from all of a panel
// (hidesAll), and where on a panel a shadow that the rules' points missed would show (probeShadow).
#include <algorithm>
#include <cmath>

#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/quadrature/shadow_clipper_detail.h"
#include "core/geometry/plane_clip.h"
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

double shadowEps(const ConvexPolygon& source, const ConvexPolygon& receiver) {
  const Vec3 cs = source.centre(), cr = receiver.centre();
  double size = (cs - cr).norm();
  for (int k = 0; k < source.count; ++k)
    size = std::max(size, (source.v[static_cast<std::size_t>(k)] - cr).norm());
  return 1e-10 * size;
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

bool ShadowClipper::hidesAll(const Vec3* panel, int count, const std::vector<int>& occluders,
                             bool bySolids) const {
  int lastSolid = -1;
  for (int index : occluders) {
    const Occluder& o = prepared_[static_cast<std::size_t>(index)];
    if (polygonCutsEverySegment(panel, count, receiver_.v.data(), receiver_.count, o.polygon.v.data(),
                                o.polygon.count, o.normal, o.normal.dot(o.centre), eps_))
      return true;
    // A block's faces may share the segments between them; its cross-sections hold them all.
    if (!bySolids || o.solid < 0 || o.solid == lastSolid || !solidCentres_) continue;
    lastSolid = o.solid;
    if (solidCutsEverySegment(panel, count, receiver_.v.data(), receiver_.count,
                              solids_[static_cast<std::size_t>(o.solid)],
                              (*solidCentres_)[static_cast<std::size_t>(o.solid)], eps_))
      return true;
  }
  return false;
}

double ShadowClipper::probeShadow(const SourcePanel& panel, const std::vector<int>& occluders,
                                  long& points) const {
  const Vec3& origin = panel.v[0];
  double best = 0;
  ConvexPolygon projected, clipped;
  // The panel's edge planes (through its edges along the source's normal, facing in), found once for all
  // probes.
  Vec3 edgeNormals[4];
  double margins2[4];
  for (int k = 0; k < panel.count; ++k) {
    edgeNormals[k] = sourceNormal_.cross(panel.v[static_cast<std::size_t>((k + 1) % panel.count)] -
                                         panel.v[static_cast<std::size_t>(k)]);
    margins2[k] = eps_ * eps_ * edgeNormals[k].squaredNorm();
  }
  // Projections that cover the whole panel (or the same part of it) give the same probe: evaluated once.
  Vec3 probed[64];
  int probedCount = 0;
  // Clips `projected` to the panel and probes the centre of what is left.
  auto probe = [&]() {
    if (projected.count < 3) return;
    for (int k = 0; k < panel.count; ++k) {
      const int side = splitByPlane(projected, panel.v[static_cast<std::size_t>(k)], edgeNormals[k],
                                    margins2[k], clipped, nullptr);
      if (side < 0) return;  // wholly outside the panel
      if (side == 0) {
        if (clipped.count < 3) return;
        projected.assign(clipped);
      }
    }
    const Vec3 x = projected.centre();
    for (int k = 0; k < probedCount; ++k)
      if ((probed[k] - x).cwiseAbs().maxCoeff() <= eps_) return;
    if (probedCount < 64) probed[probedCount++] = x;
    best = std::max(best, hidden(x, occluders));
    ++points;
  };
  SmallBuffer<double, ConvexPolygon::kInline> receiverHeight;
  receiverHeight.reserve(receiver_.count);
  for (int r = 0; r < receiver_.count; ++r)
    receiverHeight[r] = sourceNormal_.dot(receiver_.v[static_cast<std::size_t>(r)] - origin);
  // The point of the source plane on the line from r through o, when o lies between the plane and r (o
  // itself when it stands on the plane).
  auto through = [&](int r, const Vec3& o, double oHeight) {
    const double rHeight = receiverHeight[r];
    if (!(oHeight >= -eps_ && rHeight - oHeight > eps_)) return;
    const Vec3& rv = receiver_.v[static_cast<std::size_t>(r)];
    projected.v[static_cast<std::size_t>(projected.count++)] =
        rv + (o - rv) * (rHeight / (rHeight - oHeight));
  };
  // A solid's corner is a corner of three faces or more: each is probed once. (Its faces seen from behind,
  // though covered by those seen from the front, are probed too: their projections' centres found the
  // shadows that the front faces' missed on the 612-wall grid room, 1.2e-5 off without them.)
  std::vector<Vec3>& probedCorners = probed_;
  probedCorners.clear();
  SmallBuffer<double, ConvexPolygon::kInline> heights;  // of an occluder's corners
  for (int index : occluders) {
    const Occluder& occluder = prepared_[static_cast<std::size_t>(index)];
    const ConvexPolygon& o = occluder.polygon;
    heights.reserve(o.count);
    for (int k = 0; k < o.count; ++k)
      heights[k] = sourceNormal_.dot(o.v[static_cast<std::size_t>(k)] - origin);
    projected.v.reserve(std::max(o.count, receiver_.count));
    for (int r = 0; r < receiver_.count; ++r) {
      projected.count = 0;
      for (int k = 0; k < o.count; ++k) through(r, o.v[static_cast<std::size_t>(k)], heights[k]);
      probe();
    }
    for (int k = 0; k < o.count; ++k) {
      const Vec3& corner = o.v[static_cast<std::size_t>(k)];
      if (occluder.solid >= 0) {
        if (std::find(probedCorners.begin(), probedCorners.end(), corner) != probedCorners.end()) continue;
        probedCorners.push_back(corner);
      }
      projected.count = 0;
      for (int r = 0; r < receiver_.count; ++r) through(r, corner, heights[k]);
      probe();
    }
  }
  return best;
}

}  // namespace rt
