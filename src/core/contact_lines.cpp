#include "core/contact_lines.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/plane_clip.h"
#include "core/geometry/segment_clip.h"

namespace rt {
namespace {

// The segment a-b clipped to the convex polygon (CCW about normal); false when nothing is left or only a
// part within `tolerance` of the boundary.
bool clipToInterior(Vec3& a, Vec3& b, const Polygon& polygon, const Vec3& normal, double tolerance) {
  double t0 = 0, t1 = 1;
  const Vec3 d = b - a;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Vec3& e0 = polygon[k];
    const Vec3 inward = normal.cross(polygon[(k + 1) % polygon.size()] - e0).normalized();
    // Strictly inside, by more than the tolerance: a segment along an edge is no cut.
    const double fa = (a - e0).dot(inward) - tolerance, df = d.dot(inward);
    if (!clipRange(fa, df, kBelowTinyRate, Boundary::Open, t0, t1)) return false;
  }
  const Vec3 start = a + t0 * d, end = a + t1 * d;
  a = start;
  b = end;
  return (b - a).norm() > tolerance;
}

// Does the line through a-b pass through the piece's interior (vertices on both sides by more than
// tolerance), within the segment's extent?
bool crosses(const Polygon& piece, const Vec3& a, const Vec3& b, const Vec3& side, const Vec3& normal,
             double tolerance) {
  bool plus = false, minus = false;
  for (const Vec3& v : piece) {
    const double f = (v - a).dot(side);
    plus = plus || f > tolerance;
    minus = minus || f < -tolerance;
  }
  if (!plus || !minus) return false;
  Vec3 s = a, e = b;
  return clipToInterior(s, e, piece, normal, tolerance);
}

}  // namespace

std::vector<CutSegment> cutSegments(const Scene& scene, int index, double tolerance, double overlapGap) {
  const Patch& patch = scene.patches[static_cast<std::size_t>(index)];
  const Vec3& n = patch.normal;
  const Vec3& o = patch.vertices.front();
  Eigen::AlignedBox3d box;
  for (const Vec3& v : patch.vertices) box.extend(v);
  box.min().array() -= tolerance + std::max(overlapGap, 0.0);
  box.max().array() += tolerance + std::max(overlapGap, 0.0);
  std::vector<CutSegment> segments;
  for (std::size_t q = 0; q < scene.patches.size(); ++q) {
    const Patch& other = scene.patches[q];
    if (static_cast<int>(q) == index) continue;
    const bool parallel = std::abs(other.normal.dot(n)) > 0.999;
    // A parallel patch cuts when it lies wholly in front of the plane, within the gap: its height above the
    // plane is that of its farthest vertex.
    double gap = 0;
    if (parallel) {
      if (!(overlapGap > 0)) continue;
      double lowest = std::numeric_limits<double>::infinity();
      for (const Vec3& v : other.vertices) {
        const double height = (v - o).dot(n);
        lowest = std::min(lowest, height);
        gap = std::max(gap, height);
      }
      if (lowest < -tolerance || gap > overlapGap) continue;
    }
    for (std::size_t k = 0; k < other.vertices.size(); ++k) {
      Vec3 a = other.vertices[k], b = other.vertices[(k + 1) % other.vertices.size()];
      if (!parallel && (std::abs((a - o).dot(n)) > tolerance || std::abs((b - o).dot(n)) > tolerance))
        continue;
      Eigen::AlignedBox3d edge(a.cwiseMin(b), a.cwiseMax(b));
      if (!box.intersects(edge)) continue;
      // Onto the plane exactly, then to the part strictly inside the patch.
      a -= (a - o).dot(n) * n;
      b -= (b - o).dot(n) * n;
      if (!clipToInterior(a, b, patch.vertices, n, tolerance)) continue;
      const bool known = std::any_of(segments.begin(), segments.end(), [&](const CutSegment& s) {
        return ((s.a - a).norm() < tolerance && (s.b - b).norm() < tolerance) ||
               ((s.a - b).norm() < tolerance && (s.b - a).norm() < tolerance);
      });
      if (!known) segments.push_back({a, b, static_cast<int>(q), parallel, gap});
    }
  }
  return segments;
}

std::vector<std::pair<Vec3, Vec3>> contactSegments(const Scene& scene, int index, double tolerance) {
  std::vector<std::pair<Vec3, Vec3>> out;
  for (const CutSegment& s : cutSegments(scene, index, tolerance)) out.emplace_back(s.a, s.b);
  return out;
}

std::vector<Polygon> cutAtContacts(const Scene& scene, int index, double tolerance, double overlapGap) {
  const Patch& patch = scene.patches[static_cast<std::size_t>(index)];
  std::vector<Polygon> pieces{patch.vertices};
  for (const CutSegment& segment : cutSegments(scene, index, tolerance, overlapGap)) {
    const Vec3& a = segment.a;
    const Vec3& b = segment.b;
    const Vec3 side = patch.normal.cross(b - a).normalized();
    std::vector<Polygon> next;
    for (Polygon& piece : pieces) {
      if (!crosses(piece, a, b, side, patch.normal, tolerance)) {
        next.push_back(std::move(piece));
        continue;
      }
      for (const Vec3& s : {side, Vec3(-side)}) {
        Polygon part = clipToHalfspaceTwiceOnPlane(piece, a, s);
        if (part.size() >= 3) next.push_back(std::move(part));
      }
    }
    pieces = std::move(next);
  }
  return pieces;
}

}  // namespace rt
