#include "core/refine/discontinuity.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "core/geometry/segment_clip.h"
#include "core/polygon.h"

namespace rt {
namespace {

// Which patches share each edge and which vertices neighbour each vertex, with coincident vertices of
// different patches identified: closed solids (the Cornell blocks) are several patches.
class Topology {
 public:
  Topology(const Scene& scene, double eps) : eps_(eps) {
    for (std::size_t p = 0; p < scene.patches.size(); ++p) {
      const Polygon& poly = scene.patches[p].vertices;
      for (std::size_t k = 0; k < poly.size(); ++k) {
        const int a = id(poly[k]), b = id(poly[(k + 1) % poly.size()]);
        edgeFaces_[std::minmax(a, b)].push_back(static_cast<int>(p));
        neighbours_[a].insert(b);
        neighbours_[b].insert(a);
      }
    }
  }
  int id(const Vec3& p) {
    for (std::size_t k = 0; k < points_.size(); ++k)
      if ((points_[k] - p).norm() <= eps_) return static_cast<int>(k);
    points_.push_back(p);
    return static_cast<int>(points_.size() - 1);
  }
  int find(const Vec3& p) const {
    for (std::size_t k = 0; k < points_.size(); ++k)
      if ((points_[k] - p).norm() <= eps_) return static_cast<int>(k);
    return -1;
  }
  const std::vector<int>& faces(const Vec3& a, const Vec3& b) const {
    return edgeFaces_.at(std::minmax(find(a), find(b)));
  }
  std::vector<Vec3> neighbours(const Vec3& p) const {
    std::vector<Vec3> out;
    for (int k : neighbours_.at(find(p))) out.push_back(points_[k]);
    return out;
  }

 private:
  double eps_;
  std::vector<Vec3> points_;
  std::map<std::pair<int, int>, std::vector<int>> edgeFaces_;
  std::map<int, std::set<int>> neighbours_;
};

// Restricts the parameter range [t0, t1] of a + t (b - a) to where lo <= f(t) <= hi, f linear with f(0)=fa,
// f(1)=fb: two closed half-spaces (segment_clip.h), f - lo >= 0 and hi - f >= 0.
bool restrictRange(double fa, double fb, double lo, double hi, double& t0, double& t1) {
  const double df = fb - fa;
  return clipRange(fa - lo, df, kBelowTinyRate, Boundary::Closed, t0, t1) &&
         clipRange(hi - fa, -df, kBelowTinyRate, Boundary::Closed, t0, t1);
}

bool onOneSide(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& normal, double eps) {
  bool positive = false, negative = false;
  for (const Vec3& p : points) {
    const double s = (p - origin).dot(normal);
    positive |= s > eps;
    negative |= s < -eps;
  }
  return !(positive && negative);
}

// Both endpoints on one edge of the receiver: the segment is part of its boundary, not a line inside it.
bool alongBoundary(const Vec3& a, const Vec3& b, const Polygon& polygon, double eps) {
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Vec3& e0 = polygon[k];
    const Vec3 d = (polygon[(k + 1) % polygon.size()] - e0).normalized();
    auto distance = [&](const Vec3& p) { return ((p - e0) - (p - e0).dot(d) * d).norm(); };
    if (distance(a) <= eps && distance(b) <= eps) return true;
  }
  return false;
}

class SegmentCollector {
 public:
  SegmentCollector(const Patch& receiver, double eps, double minLength)
      : receiver_(receiver), eps_(eps), minLength_(minLength) {}
  void add(CriticalSegment s) {
    if (!clipSegmentToPolygon(s.a, s.b, receiver_.vertices, receiver_.normal)) return;
    if ((s.b - s.a).norm() < std::max(minLength_, 10 * eps_)) return;
    if (alongBoundary(s.a, s.b, receiver_.vertices, 10 * eps_)) return;
    for (CriticalSegment& old : segments_) {
      const bool same = ((old.a - s.a).norm() <= 10 * eps_ && (old.b - s.b).norm() <= 10 * eps_) ||
                        ((old.a - s.b).norm() <= 10 * eps_ && (old.b - s.a).norm() <= 10 * eps_);
      if (same) {
        old.extremal = old.extremal || s.extremal;
        return;
      }
    }
    segments_.push_back(s);
  }
  std::vector<CriticalSegment>& segments() { return segments_; }

 private:
  const Patch& receiver_;
  double eps_, minLength_;
  std::vector<CriticalSegment> segments_;
};

}  // namespace

bool clipSegmentToPolygon(Vec3& a, Vec3& b, const Polygon& polygon, const Vec3& normal) {
  double t0 = 0, t1 = 1;
  const Vec3 d = b - a;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Vec3& e0 = polygon[k];
    const Vec3 inward = normal.cross(polygon[(k + 1) % polygon.size()] - e0).normalized();
    const double fa = (a - e0).dot(inward), df = d.dot(inward);
    if (!restrictRange(fa, fa + df, 0.0, std::numeric_limits<double>::infinity(), t0, t1)) return false;
  }
  const Vec3 start = a + t0 * d, end = a + t1 * d;
  a = start;
  b = end;
  return true;
}

std::vector<CriticalSegment> criticalSegments(const Scene& scene, int receiverIndex, double minLength) {
  const Eigen::AlignedBox3d box = scene.bounds();
  const double eps = 1e-9 * (box.isEmpty() ? 1.0 : box.diagonal().norm());
  const Topology topology(scene, eps);
  const Patch& receiver = scene.patches[receiverIndex];
  const Vec3 nR = receiver.normal;
  const Vec3& r0 = receiver.vertices[0];
  auto dR = [&](const Vec3& p) { return (p - r0).dot(nR); };
  SegmentCollector out(receiver, eps, minLength);

  for (std::size_t l = 0; l < scene.patches.size(); ++l) {
    const Patch& light = scene.patches[l];
    if (static_cast<int>(l) == receiverIndex || !scene.materialOf(light).isEmitter()) continue;
    const Polygon& L = light.vertices;
    auto dL = [&](const Vec3& p) { return (p - L[0]).dot(light.normal); };
    if (std::none_of(L.begin(), L.end(), [&](const Vec3& v) { return dR(v) > eps; })) continue;
    if (std::none_of(receiver.vertices.begin(), receiver.vertices.end(),
                     [&](const Vec3& v) { return dL(v) > eps; }))
      continue;
    for (std::size_t o = 0; o < scene.patches.size(); ++o) {
      if (o == l || static_cast<int>(o) == receiverIndex) continue;
      const Patch& occluder = scene.patches[o];
      const Polygon& O = occluder.vertices;
      if (std::none_of(O.begin(), O.end(), [&](const Vec3& v) { return dR(v) > eps && dL(v) > eps; }))
        continue;

      // VE: light vertex v, occluder edge a-b; the edge's shadow from v.
      for (const Vec3& v : L) {
        const double hv = dR(v);
        if (hv <= eps) continue;
        for (std::size_t k = 0; k < O.size(); ++k) {
          const Vec3& a = O[k];
          const Vec3& b = O[(k + 1) % O.size()];
          const std::vector<int>& faces = topology.faces(a, b);
          if (faces.size() >= 2) {
            int front = 0;
            for (int f : faces) front += (v - scene.patches[f].vertices[0]).dot(scene.patches[f].normal) > 0;
            if (front == 0 || front == static_cast<int>(faces.size())) continue;  // not a silhouette from v
          }
          double t0 = 0, t1 = 1;
          if (!restrictRange(dR(a), dR(b), 0, hv * (1 - 1e-6), t0, t1)) continue;
          if (!restrictRange(dL(a), dL(b), 0, std::numeric_limits<double>::infinity(), t0, t1)) continue;
          auto project = [&](const Vec3& p) { return Vec3(v + (p - v) * (hv / (hv - dR(p)))); };
          CriticalSegment s;
          s.a = project(a + t0 * (b - a));
          s.b = project(a + t1 * (b - a));
          s.receiver = receiverIndex;
          s.light = static_cast<int>(l);
          s.occluder = static_cast<int>(o);
          s.kind = CriticalSegment::Kind::VE;
          s.extremal = onOneSide(L, v, (a - v).cross(b - v).normalized(), eps);
          out.add(s);
        }
      }
      // EV: occluder vertex u, light edge c-d; u's shadows from the points of the edge.
      for (const Vec3& u : O) {
        const double hu = dR(u);
        if (hu < -eps || dL(u) <= eps) continue;
        const std::vector<Vec3> around = topology.neighbours(u);
        for (std::size_t k = 0; k < L.size(); ++k) {
          const Vec3& c = L[k];
          const Vec3& d = L[(k + 1) % L.size()];
          const Vec3 m = (d - c).cross(u - c);
          if (m.norm() <= eps * eps || !onOneSide(around, u, m.normalized(), eps))
            continue;  // plane cuts the solid
          double t0 = 0, t1 = 1;
          if (!restrictRange(dR(c), dR(d), hu + std::max(hu, eps) * 1e-6,
                             std::numeric_limits<double>::infinity(), t0, t1))
            continue;
          auto project = [&](const Vec3& p) { return Vec3(p + (u - p) * (dR(p) / (dR(p) - hu))); };
          CriticalSegment s;
          s.a = project(c + t0 * (d - c));
          s.b = project(c + t1 * (d - c));
          s.receiver = receiverIndex;
          s.light = static_cast<int>(l);
          s.occluder = static_cast<int>(o);
          s.kind = CriticalSegment::Kind::EV;
          s.extremal = true;
          out.add(s);
        }
      }
    }
  }
  return std::move(out.segments());
}

std::vector<CriticalSegment> criticalSegments(const Scene& scene, double minLength) {
  std::vector<CriticalSegment> all;
  for (std::size_t r = 0; r < scene.patches.size(); ++r) {
    if (scene.materialOfPatch(static_cast<int>(r)).isEmitter()) continue;
    auto some = criticalSegments(scene, static_cast<int>(r), minLength);
    all.insert(all.end(), some.begin(), some.end());
  }
  return all;
}

}  // namespace rt
