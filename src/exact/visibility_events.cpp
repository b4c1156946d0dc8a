#include "exact/visibility_events.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/geometry/segment_clip.h"
#include "core/polygon.h"
#include "exact/geometry_util.h"

namespace rt::exact {
namespace {

struct Edge {
  Vec3 a, b;
  bool receiver;
  // The occluder parts the edge bounds (indices into blockingParts(); -1: none, or more than two). Both set
  // for a crease, the edge of two non-coplanar parts (a prism's side and its cap, two neighbouring sides).
  int face = -1, otherFace = -1;
};

struct Vertex {
  Vec3 p;
  bool receiver;
};

bool near(const Vec3& p, const Vec3& q, double eps) {
  return (p - q).squaredNorm() <= eps * eps;
}

// The occluders as they can block: clipped to the half-spaces in front of the source and of the receiver
// (both fixed for the pair), dropping what lies in either plane.
std::vector<Polygon> blockingParts(const PairGeometry& pair, double eps) {
  std::vector<Polygon> parts;
  const Vec3& s0 = pair.sourcePolygon.front();
  const Vec3& r0 = pair.receiverPolygon.front();
  for (const Polygon& occluder : pair.blockers) {
    Polygon o = clipToHalfspace(occluder, s0, pair.sourceNormal);
    if (o.size() >= 3) o = clipToHalfspace(o, r0, pair.receiverNormal);
    if (o.size() < 3) continue;
    if (distanceRange(o, s0, pair.sourceNormal).second <= eps) continue;
    if (distanceRange(o, r0, pair.receiverNormal).second <= eps) continue;
    parts.push_back(std::move(o));
  }
  return parts;
}

// Edges that may bound the union of the occluders' shadows: all but those shared (reversed) by two coplanar
// occluders, whose shadows then lie on both sides of the edge's shadow.
std::vector<Edge> boundaryEdges(const std::vector<Polygon>& parts, double eps) {
  std::vector<Vec3> normals;
  for (const Polygon& p : parts) normals.push_back(newellNormal(p).normalized());
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Polygon& p = parts[i];
    for (std::size_t k = 0; k < p.size(); ++k) {
      const Vec3& a = p[k];
      const Vec3& b = p[(k + 1) % p.size()];
      if (near(a, b, eps)) continue;
      bool inner = false;
      for (std::size_t j = 0; j < parts.size() && !inner; ++j) {
        if (j == i || normals[i].dot(normals[j]) < 1 - 1e-9) continue;
        if (std::abs(normals[i].dot(parts[j].front() - p.front())) > eps) continue;
        const Polygon& q = parts[j];
        for (std::size_t m = 0; m < q.size() && !inner; ++m)
          inner = near(q[m], b, eps) && near(q[(m + 1) % q.size()], a, eps);
      }
      if (inner) continue;
      bool duplicate = false;  // the same edge of two non-coplanar occluders (a crease): one is enough
      for (Edge& e : edges)
        if ((near(e.a, b, eps) && near(e.b, a, eps)) || (near(e.a, a, eps) && near(e.b, b, eps))) {
          duplicate = true;
          if (e.otherFace < 0)
            e.otherFace = static_cast<int>(i);
          else
            e.face = -1;  // bounds three parts or more: no crease to reason about
        }
      if (!duplicate) edges.push_back({a, b, false, static_cast<int>(i), -1});
    }
  }
  return edges;
}

// Corners of the shadow boundary: endpoints of boundary edges where the boundary turns. A vertex in the
// middle of a straight run of edges (a block's edge split by the mesh) is no event vertex.
std::vector<Vertex> cornerVertices(const std::vector<Edge>& edges, double eps) {
  struct Group {
    Vec3 p;
    std::vector<Vec3> directions;
  };
  std::vector<Group> groups;
  auto add = [&](const Vec3& p, const Vec3& direction) {
    for (Group& g : groups)
      if (near(g.p, p, eps)) {
        g.directions.push_back(direction);
        return;
      }
    groups.push_back({p, {direction}});
  };
  for (const Edge& e : edges) {
    const Vec3 d = (e.b - e.a).normalized();
    add(e.a, d);
    add(e.b, d);
  }
  std::vector<Vertex> corners;
  for (const Group& g : groups) {
    bool turns = false;
    for (const Vec3& d : g.directions) turns = turns || d.cross(g.directions.front()).norm() > 1e-9;
    if (turns) corners.push_back({g.p, false});
  }
  return corners;
}

// The parameter interval [lo, hi] of the line p + t d inside the convex polygon (in the line's plane).
// Edges of no length to rounding are skipped: a cell cut along a line through one of its corners can keep
// that corner twice, ~1e-12 apart, and the direction between the two copies is noise (it once bounded the
// chord of an event line from that corner to nothing, and a block's contact corner went uncut).
bool chord(const Polygon& polygon, const Vec3& normal, const Vec3& p, const Vec3& d, double& lo, double& hi) {
  lo = -INFINITY;
  hi = INFINITY;
  Vec3 centre = Vec3::Zero();
  for (const Vec3& c : polygon) centre += c;
  centre /= static_cast<double>(polygon.size());
  double size2 = 0;
  for (const Vec3& c : polygon) size2 = std::max(size2, (c - centre).squaredNorm());
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Vec3& c = polygon[k];
    const Vec3 edge = polygon[(k + 1) % polygon.size()] - c;
    if (edge.squaredNorm() <= 1e-18 * size2) continue;
    Vec3 m = normal.cross(edge);
    if (m.dot(centre - c) < 0) m = -m;
    // Inside: f0 + t f1 >= 0 (a chord along an edge is kept).
    if (!clipRange(m.dot(p - c), m.dot(d), 0.0, Boundary::Closed, lo, hi)) return false;
  }
  return lo < hi;
}

// The side of the plane (through `origin`, normal n) that the convex part lies on when the plane holds one
// of its edges: the sign of its farthest corner (0: in the plane).
int sideOf(const Polygon& part, const Vec3& origin, const Vec3& n, double eps) {
  double far = 0;
  for (const Vec3& c : part) {
    const double d = n.dot(c - origin);
    if (std::abs(d) > std::abs(far)) far = d;
  }
  return far > eps ? 1 : far < -eps ? -1 : 0;
}

// The part of the source domain where vertex v and edge [a, b] line up as seen from x: the line where the
// plane through v, a, b meets the source plane, restricted to the double wedge at v spanned by a and b.
// From x on that plane, the plane through x and the edge is the same plane; when it has the two parts of a
// crease on opposite sides, the edge is no silhouette edge from x (the line of sight along it passes
// between them, into the solid), its shadow no boundary of the shadows, and the alignment no event. A
// convex solid's vertex and edge line up so unless they share a face: of the thousands of vertex-edge
// planes of a prism, only its face planes are left.
void addEvent(const Vertex& v, const Edge& e, const std::vector<Polygon>& parts, const Polygon& domain,
              const Vec3& s0, const Vec3& ns, double eps, std::vector<EventSegment>& out) {
  if (near(v.p, e.a, eps) || near(v.p, e.b, eps)) return;
  const Vec3 u = e.a - v.p, w = e.b - v.p;
  const Vec3 n = u.cross(w);
  const double nn = n.squaredNorm();
  if (nn <= 1e-18 * u.squaredNorm() * w.squaredNorm()) return;  // v on the edge's line
  if (e.face >= 0 && e.otherFace >= 0) {
    const Vec3 unit = n / std::sqrt(nn);
    if (sideOf(parts[static_cast<std::size_t>(e.face)], e.a, unit, eps) *
            sideOf(parts[static_cast<std::size_t>(e.otherFace)], e.a, unit, eps) <
        0)
      return;
  }
  Vec3 d = n.cross(ns);
  if (d.squaredNorm() <= 1e-18 * nn) return;  // the plane is parallel to the source plane
  d.normalize();
  // A point on both planes: n . y = n . v and ns . y = ns . s0.
  const double h1 = n.dot(v.p), h2 = ns.dot(s0), n12 = n.dot(ns);
  const double det = nn - n12 * n12;  // |ns| = 1
  const Vec3 p = ((h1 - h2 * n12) * n + (h2 * nn - h1 * n12) * ns) / det;
  double lo, hi;
  if (!chord(domain, ns, p, d, lo, hi)) return;
  // y - v = alpha u + beta w, both linear in t; the event needs alpha beta >= 0.
  auto alpha = [&](double t) { return (p + t * d - v.p).cross(w).dot(n) / nn; };
  auto beta = [&](double t) { return u.cross(p + t * d - v.p).dot(n) / nn; };
  std::vector<double> cuts{lo, hi};
  for (const auto& f : {std::function<double(double)>(alpha), std::function<double(double)>(beta)}) {
    const double f0 = f(0), slope = f(1) - f0;
    if (slope != 0) {
      const double root = -f0 / slope;
      if (root > lo && root < hi) cuts.push_back(root);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double mid = 0.5 * (cuts[k] + cuts[k + 1]);
    if (cuts[k + 1] - cuts[k] > eps && alpha(mid) * beta(mid) >= 0)
      out.push_back({p + cuts[k] * d, p + cuts[k + 1] * d});
  }
}

}  // namespace

std::vector<EventSegment> visibilityEvents(const PairGeometry& pair) {
  std::vector<EventSegment> events;
  if (!pair.facing || pair.blockers.empty() || pair.integrationDomain.size() < 3) return events;
  const double eps = kGeometricEpsilon * pair.scale * 10;
  const Vec3& s0 = pair.sourcePolygon.front();
  const Vec3& ns = pair.sourceNormal;
  const Polygon receiver = clipToHalfspace(pair.receiverPolygon, s0, ns);
  if (receiver.size() < 3) return events;
  const std::vector<Polygon> parts = blockingParts(pair, eps);
  if (parts.empty()) return events;

  std::vector<Edge> edges = boundaryEdges(parts, eps);
  std::vector<Vertex> vertices = cornerVertices(edges, eps);
  const std::size_t occluderEdges = edges.size(), occluderVertices = vertices.size();
  for (std::size_t k = 0; k < receiver.size(); ++k) {
    edges.push_back({receiver[k], receiver[(k + 1) % receiver.size()], true, -1, -1});
    vertices.push_back({receiver[k], true});
  }
  for (std::size_t i = 0; i < vertices.size(); ++i)
    for (std::size_t j = 0; j < edges.size(); ++j)
      if (i < occluderVertices || j < occluderEdges)
        addEvent(vertices[i], edges[j], parts, pair.integrationDomain, s0, ns, eps, events);
  return events;
}

std::vector<Polygon> splitAlongEvents(const Polygon& domain, const Vec3& normal,
                                      const std::vector<EventSegment>& events, double margin,
                                      std::size_t maxCells) {
  struct Work {
    Polygon cell;
    std::vector<int> candidates;  // events that crossed the parent: no other can cross this cell
  };
  std::vector<Polygon> cells;
  std::vector<Work> work;
  std::vector<int> all(events.size());
  for (std::size_t k = 0; k < events.size(); ++k) all[k] = static_cast<int>(k);
  work.push_back({domain, std::move(all)});
  while (!work.empty()) {
    Work item = std::move(work.back());
    work.pop_back();
    if (cells.size() + work.size() + 1 >= maxCells) {
      cells.push_back(std::move(item.cell));
      continue;
    }
    std::vector<int> crossing;
    for (int k : item.candidates) {
      const EventSegment& e = events[k];
      const Vec3 d = e.b - e.a;
      const double length = d.norm();
      if (length <= margin) continue;
      const Vec3 m = d.cross(normal) / length;
      double lo = INFINITY, hi = -INFINITY;
      for (const Vec3& c : item.cell) {
        const double s = m.dot(c - e.a);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
      }
      if (lo >= -margin || hi <= margin) continue;
      double t0, t1;  // chord of the line in the cell, in units of the segment's length
      if (!chord(item.cell, normal, e.a, d / length, t0, t1)) continue;
      if (std::min(t1, length) - std::max(t0, 0.0) > margin) crossing.push_back(k);
    }
    if (crossing.empty()) {
      cells.push_back(std::move(item.cell));
      continue;
    }
    const EventSegment& e = events[crossing.front()];
    const Vec3 m = (e.b - e.a).cross(normal).normalized();
    crossing.erase(crossing.begin());
    for (const Vec3& side : {m, Vec3(-m)}) {
      Polygon half = clipToHalfspace(item.cell, e.a, side);
      if (half.size() >= 3) work.push_back({std::move(half), crossing});
    }
  }
  return cells;
}

}  // namespace rt::exact
