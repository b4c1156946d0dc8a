#include "core/formfactor/quadrature/visibility_events.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/formfactor/quadrature/solid_silhouette.h"
#include "core/geometry/plane_clip.h"
#include "core/geometry/segment_clip.h"

namespace rt {

namespace {

// Whether some point p + t d, t in [0, 1], lies in each of `count` half-planes, the k-th given by
// `halfPlane(k)` as its height at p and the height's change along d (inside where the height is >= 0): the
// segment clipped to a convex region (segment_clip.h; a parallel segment on a boundary is in).
template <class HalfPlane>
bool segmentKeepsAPoint(int count, HalfPlane&& halfPlane) {
  double t0 = 0, t1 = 1;
  for (int k = 0; k < count; ++k) {
    const auto [start, rate] = halfPlane(k);
    if (!clipRange(start, rate, kTinyRate, Boundary::Closed, t0, t1)) return false;
  }
  return true;
}

// The source as the events see it: its plane and its edges' inward normals within that plane.
class SourceRegion {
 public:
  SourceRegion(const ConvexPolygon& source, const Vec3& normal, double eps)
      : source_(source), normal_(normal), eps_(eps) {}

  double height(const Vec3& p) const { return normal_.dot(p - source_.v[0]); }

  // The source's corners strictly on both sides of the plane: its line crosses the source's inside.
  bool crossedBy(const Vec3& origin, const Vec3& normal) const {
    const double margin = eps_ * normal.norm();
    bool above = false, below = false;
    for (int k = 0; k < source_.count; ++k) {
      const double d = normal.dot(source_.v[static_cast<std::size_t>(k)] - origin);
      above |= d > margin;
      below |= d < -margin;
    }
    return above && below;
  }

  // The segment pq of the source's plane passes through the source's inside (by more than eps).
  bool meetsSegment(const Vec3& p, const Vec3& q) const {
    if (!inwardMade_) makeInward();
    const Vec3 d = q - p;
    return segmentKeepsAPoint(source_.count, [&](int k) {
      const Vec3& n = inward_[static_cast<std::size_t>(k)];
      return std::pair{n.dot(p - source_.v[static_cast<std::size_t>(k)]) - eps_, n.dot(d)};
    });
  }

  // The event plane's line where it matters: the projection of the segment ab from the centre c onto the
  // source's plane (the points x from which c lies in line behind a point of ab), given the three heights.
  // Lines from which c cannot be behind ab (ab no nearer the plane than c) are dropped before this; where
  // only part of ab is nearer, the projection is unbounded and the whole line is tested.
  // A bounded segment is kept in `plane`, so that cells it misses are not cut along it.
  bool matters(const Vec3& c, double hc, const Vec3& a, double ha, const Vec3& b, double hb,
               EventPlane& plane) const {
    // The line must cross the source at all: four products, where the segment's test takes divisions, and
    // most event planes pass clear of a small source.
    if (!crossedBy(c, plane.normal)) return false;
    if (ha < -eps_ || hb < -eps_ || ha >= hc - eps_ || hb >= hc - eps_) return true;
    plane.from = c + (a - c) * (hc / (hc - ha));
    plane.to = c + (b - c) * (hc / (hc - hb));
    plane.bounded = true;
    return meetsSegment(plane.from, plane.to);
  }

 private:
  const ConvexPolygon& source_;
  Vec3 normal_;
  double eps_;
  // The edges' unit inward normals, made on the first segment's test (most pairs have none).
  void makeInward() const {
    const Vec3 centre = source_.centre();
    inward_.reserve(source_.count);
    for (int k = 0; k < source_.count; ++k) {
      const Vec3& p = source_.v[static_cast<std::size_t>(k)];
      Vec3 inward = normal_.cross(source_.v[static_cast<std::size_t>((k + 1) % source_.count)] - p);
      if (inward.dot(centre - p) < 0) inward = -inward;
      const double length = inward.norm();
      inward_[static_cast<std::size_t>(k)] = length > 0 ? Vec3(inward / length) : Vec3::Zero();
    }
    inwardMade_ = true;
  }
  mutable SmallBuffer<Vec3, ConvexPolygon::kInline> inward_;
  mutable bool inwardMade_ = false;
};

// Whether the segment pq of the cell's plane comes within `eps` of the convex cell (`normal` the plane's).
// `normal` is one the cell turns counter-clockwise about, so that normal x edge points inward, and `margin`
// bounds eps times the length of any such product (|normal| times the cell's longest edge).
bool segmentMeetsCell(const ConvexPolygon& cell, const Vec3& normal, const Vec3& p, const Vec3& q,
                      double margin) {
  const Vec3 d = q - p;
  return segmentKeepsAPoint(cell.count, [&](int k) {
    const Vec3& a = cell.v[static_cast<std::size_t>(k)];
    const Vec3 inward = normal.cross(cell.v[static_cast<std::size_t>((k + 1) % cell.count)] - a);
    return std::pair{inward.dot(p - a) + margin, inward.dot(d)};
  });
}

}  // namespace

bool ShadowClipper::eventPlanes(const ConvexPolygon& source, const std::vector<int>& occluders,
                                std::vector<EventPlane>& out) const {
  out.clear();
  if (occluders.empty()) return true;
  const int solid = prepared_[static_cast<std::size_t>(occluders[0])].solid;
  if (solid < 0 && occluders.size() > 1) return false;
  int second = -1;  // another whole solid
  for (int k : occluders) {
    const int other = prepared_[static_cast<std::size_t>(k)].solid;
    if (other == solid || other == second) continue;
    if (other < 0 || second >= 0) return false;
    second = other;
  }
  auto isWhole = [&](int s) { return s >= 0 && shapes_ && whole_[static_cast<std::size_t>(s)] == 1; };
  if (second >= 0 && !(isWhole(solid) && isWhole(second))) return false;
  const SourceRegion region(source, sourceNormal_, eps_);
  const double tiny = 1e-24 * (eps_ * 1e10) * (eps_ * 1e10);  // a cross product of no direction
  // Receiver corner r behind occluder edge ab (EV), and occluder corner v in front of receiver edge r1 r2
  // (VE): from x the point nearer the source's plane hides the one farther. Heights first: most candidates
  // end there, before any cross product.
  SmallBuffer<double, ConvexPolygon::kInline> receiverHeight;
  receiverHeight.reserve(receiver_.count);
  for (int k = 0; k < receiver_.count; ++k)
    receiverHeight[static_cast<std::size_t>(k)] = region.height(receiver_.v[static_cast<std::size_t>(k)]);
  auto edgeEvents = [&](const Vec3& a, const Vec3& b) {
    const double ha = region.height(a), hb = region.height(b);
    for (int k = 0; k < receiver_.count; ++k) {
      const double hr = receiverHeight[static_cast<std::size_t>(k)];
      if (ha >= hr - eps_ && hb >= hr - eps_) continue;  // ab no nearer the source than r: never in front
      const Vec3& r = receiver_.v[static_cast<std::size_t>(k)];
      EventPlane plane{r, (a - r).cross(b - r)};
      if (plane.normal.squaredNorm() > tiny * tiny && region.matters(r, hr, a, ha, b, hb, plane))
        out.push_back(plane);
    }
  };
  auto cornerEvents = [&](const Vec3& v) {
    const double hv = region.height(v);
    for (int k = 0; k < receiver_.count; ++k) {
      const int next = (k + 1) % receiver_.count;
      const double h1 = receiverHeight[static_cast<std::size_t>(k)],
                   h2 = receiverHeight[static_cast<std::size_t>(next)];
      if (h1 <= hv + eps_ && h2 <= hv + eps_) continue;
      const Vec3 &r1 = receiver_.v[static_cast<std::size_t>(k)],
                 &r2 = receiver_.v[static_cast<std::size_t>(next)];
      EventPlane plane{v, (r1 - v).cross(r2 - v)};
      if (plane.normal.squaredNorm() <= tiny * tiny || !region.crossedBy(v, plane.normal)) continue;
      // From x, v hides a point p of r1 r2: x = p + (v - p) t, so x is p's projection through v, and the
      // segment of them is the projection of r1 r2 from each end's point through v.
      if (!(hv < -eps_ || h1 <= hv + eps_ || h2 <= hv + eps_)) {
        plane.from = r1 + (v - r1) * (h1 / (h1 - hv));
        plane.to = r2 + (v - r2) * (h2 / (h2 - hv));
        plane.bounded = true;
        if (!region.meetsSegment(plane.from, plane.to)) continue;
      }
      out.push_back(plane);
    }
  };
  auto faceEvent = [&](const Vec3& origin, const Vec3& normal) {
    if (region.crossedBy(origin, normal)) out.push_back({origin, normal});
  };

  // A whole solid: its edges that are on the silhouette from some point of the source (their two faces not
  // both seen from the front, nor both from behind, from all of it), and their corners. Those edges and
  // corners are marked in `edgeUsed` and `cornerUsed` for the events between two solids. Every edge, corner
  // and face has its mark: one left out would leave its events out, and a cell across them would be taken
  // as one form.
  using Marks = SmallBuffer<bool, 64>;
  auto solidEvents = [&](const SolidShape& shape, Marks& edgeUsed, Marks& cornerUsed) {
    const std::size_t faces = shape.planes.size();
    SmallBuffer<signed char, 64> facing;  // per face: 1 all front, -1 all behind, 0 mixed or edge-on
    facing.assign(static_cast<int>(faces), 0);
    edgeUsed.assign(static_cast<int>(shape.edges.size()), false);
    cornerUsed.assign(static_cast<int>(shape.corners.size()), false);
    for (std::size_t f = 0; f < faces; ++f) {
      const auto& [n, offset] = shape.planes[f];
      bool front = true, behind = true;
      for (int k = 0; k < source.count; ++k) {
        const double d = n.dot(source.v[static_cast<std::size_t>(k)]) - offset;
        front &= d > eps_;
        behind &= d < -eps_;
      }
      facing[f] = front ? 1 : behind ? -1 : 0;
      if (!front && !behind) faceEvent(n * offset, n);
    }
    for (std::size_t e = 0; e < shape.edges.size(); ++e) {
      const SolidShape::Edge& edge = shape.edges[e];
      const signed char l = facing[static_cast<std::size_t>(edge.left)],
                        r = facing[static_cast<std::size_t>(edge.right)];
      if (l != 0 && l == r) continue;
      edgeUsed[e] = true;
      edgeEvents(shape.corners[static_cast<std::size_t>(edge.a)],
                 shape.corners[static_cast<std::size_t>(edge.b)]);
      for (int c : {edge.a, edge.b}) cornerUsed[static_cast<std::size_t>(c)] = true;
    }
    for (std::size_t c = 0; c < shape.corners.size(); ++c)
      if (cornerUsed[c]) cornerEvents(shape.corners[c]);
  };
  if (isWhole(solid) && second < 0) {
    Marks edges, corners;
    solidEvents((*shapes_)[static_cast<std::size_t>(solid)], edges, corners);
    return true;
  }
  if (second >= 0) {
    // Two whole solids: each one's events, and where the shadow of a silhouette corner of one crosses the
    // shadow of a silhouette edge of the other (x in the plane of that corner and edge). What is left, the
    // crossing of two shadow edges sliding over a receiver edge, is not a plane (visibility_events.h).
    const std::array<const SolidShape*, 2> shapes = {&(*shapes_)[static_cast<std::size_t>(solid)],
                                                     &(*shapes_)[static_cast<std::size_t>(second)]};
    std::array<Marks, 2> edges, corners;
    for (std::size_t s = 0; s < 2; ++s) solidEvents(*shapes[s], edges[s], corners[s]);
    for (std::size_t s = 0; s < 2; ++s) {
      const SolidShape &one = *shapes[s], &other = *shapes[1 - s];
      for (std::size_t c = 0; c < one.corners.size(); ++c) {
        if (!corners[s][c]) continue;
        const Vec3& v = one.corners[c];
        const double hv = region.height(v);
        for (std::size_t e = 0; e < other.edges.size(); ++e) {
          if (!edges[1 - s][e]) continue;
          const Vec3 &a = other.corners[static_cast<std::size_t>(other.edges[e].a)],
                     &b = other.corners[static_cast<std::size_t>(other.edges[e].b)];
          EventPlane plane{v, (a - v).cross(b - v)};
          if (plane.normal.squaredNorm() <= tiny * tiny || !region.crossedBy(v, plane.normal)) continue;
          // x lines up with v and a point p of ab at x = v + (p - v) hv / (hv - hp): a segment of the line
          // where ab lies wholly nearer the source's plane than v or wholly farther.
          const double ha = region.height(a), hb = region.height(b);
          if ((ha < hv - eps_ && hb < hv - eps_) || (ha > hv + eps_ && hb > hv + eps_)) {
            plane.from = v + (a - v) * (hv / (hv - ha));
            plane.to = v + (b - v) * (hv / (hv - hb));
            plane.bounded = true;
            if (!region.meetsSegment(plane.from, plane.to)) continue;
          }
          out.push_back(plane);
        }
      }
    }
    return true;
  }
  // A polygon, or a solid cut by the source's or the receiver's plane (its clipped faces): every edge and
  // corner (a truncated convex solid is still convex, so its silhouette is among them).
  for (int index : occluders) {
    const Occluder& o = prepared_[static_cast<std::size_t>(index)];
    const int m = o.polygon.count;
    for (int k = 0; k < m; ++k) {
      edgeEvents(o.polygon.v[static_cast<std::size_t>(k)],
                 o.polygon.v[static_cast<std::size_t>((k + 1) % m)]);
      cornerEvents(o.polygon.v[static_cast<std::size_t>(k)]);
    }
    faceEvent(o.centre, o.normal);
  }
  return true;
}

bool cutAlongEvents(const SourcePanel& panel, const std::vector<EventPlane>& planes, double eps, int maxCells,
                    std::vector<ConvexPolygon>& cells) {
  const std::size_t first = cells.size();
  cells.emplace_back().assign(panel);
  ConvexPolygon front, back;
  // The panel's own normal: it and every cell cut from it turn counter-clockwise about it. Any cell's edge is
  // no longer than twice the panel's longest.
  const Vec3 normal = twiceAreaVector(panel.data(), panel.count);
  const double margin = eps * normal.norm() * 2 * panel.longestEdge();
  for (const EventPlane& plane : planes) {
    const double margin2 = eps * eps * plane.normal.squaredNorm();
    const std::size_t end = cells.size();
    for (std::size_t c = first; c < end; ++c) {
      if (splitByPlane(cells[c], plane.origin, plane.normal, margin2, front, &back) != 0) continue;
      if (front.count < 3 || back.count < 3) continue;  // a sliver below the margin: not worth a cell
      // The event happens on part of the line only: a cell that part misses keeps its form across the line.
      if (plane.bounded && !segmentMeetsCell(cells[c], normal, plane.from, plane.to, margin)) continue;
      if (static_cast<int>(cells.size() - first) >= maxCells) {
        cells.resize(first);
        return false;
      }
      // (Corner by corner: a whole ConvexPolygon is 800 bytes.)
      cells[c].assign(front);
      cells.emplace_back().assign(back);
    }
  }
  return true;
}

}  // namespace rt
