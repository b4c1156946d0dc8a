#include "core/formfactor/quadrature/near_edges.h"

#include <algorithm>
#include <cmath>

#include "core/formfactor/quadrature/unoccluded_integral.h"
#include "core/geometry/plane_clip.h"

namespace rt {
namespace {

// Strips per side of the edge's line: widths at least double from one to the next, so this many reach from
// the edge's height to 2^kMaxStrips times it; an edge lower than that over a cell is left to the rules in
// its innermost strip.
constexpr int kMaxStrips = 20;
// Heights and lengths below this share of the cells' size are taken as none: an edge on the plane (a block
// standing on it) is cut around (QuadraturePair) or meets the cells at their edge, not beyond it.
constexpr double kOnPlane = 1e-9;
// A cell counts as too wide beyond this many times its distance from the edge; strips() cuts them no wider
// than once, so that its strips (and their parts) are never too wide for it again.
constexpr double kTooWide = 1.25;

}  // namespace

void NearEdges::find(const ShadowClipper& clipper, const std::vector<int>& occluders, double reach,
                     double tolerance) {
  edges_.clear();
  const Vec3 origin = clipper.sourceOrigin();
  const Vec3 n = clipper.sourceNormal().normalized();
  const double low = kOnPlane * reach;
  for (int k : occluders) {
    const ConvexPolygon& polygon = clipper.polygonOf(k);
    for (int c = 0; c < polygon.count; ++c) {
      const Vec3& p = polygon.v[static_cast<std::size_t>(c)];
      const Vec3& q = polygon.v[static_cast<std::size_t>((c + 1) % polygon.count)];
      const double hp = n.dot(p - origin), hq = n.dot(q - origin);
      const double height = std::min(hp, hq);
      if (!(height > low) || !(height < reach)) continue;
      Edge e;
      e.a = p - hp * n;
      const Vec3 d = (q - hq * n) - e.a;
      e.length = d.norm();
      if (!(e.length > low)) continue;
      // The integral over a strip of h / d, d from h to the cells' size, along the edge's length.
      if (e.length * height * (1 + std::log(reach / height)) < tolerance) continue;
      e.along = d / e.length;
      e.across = n.cross(e.along);
      e.height = height;
      edges_.push_back(e);
    }
  }
}

NearEdges::Extent NearEdges::extentOf(const SourcePanel& cell, const Edge& e) const {
  Extent x{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (int k = 0; k < cell.count; ++k) {
    const Vec3 r = cell.v[static_cast<std::size_t>(k)] - e.a;
    const double s = e.along.dot(r), t = e.across.dot(r);
    x.s0 = std::min(x.s0, s);
    x.s1 = std::max(x.s1, s);
    x.t0 = std::min(x.t0, t);
    x.t1 = std::max(x.t1, t);
  }
  return x;
}

double NearEdges::offAcross(const Extent& x, const Edge& e) {
  const double along = std::max({0.0, x.s0 - e.length, -x.s1});
  return std::sqrt(along * along + e.height * e.height);
}

int NearEdges::tooWide(const SourcePanel& cell, int except) const {
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    if (static_cast<int>(k) == except) continue;
    const Edge& e = edges_[k];
    const Extent x = extentOf(cell, e);
    const double gap = x.t0 > 0 ? x.t0 : (x.t1 < 0 ? -x.t1 : 0);
    const double off = offAcross(x, e);
    const double width = x.t1 - x.t0;
    if (width * width > kTooWide * kTooWide * (gap * gap + off * off)) return static_cast<int>(k);
  }
  return -1;
}

Vec3 NearEdges::nearestPoint(const SourcePanel& cell, int edge) const {
  const Edge& e = edges_[static_cast<std::size_t>(edge)];
  auto distance2 = [&](const Vec3& p) {
    const Vec3 r = p - e.a;
    const double s = e.along.dot(r), t = e.across.dot(r);
    const double along = std::max({0.0, s - e.length, -s});
    return along * along + t * t;
  };
  Vec3 best = cell.v[0];
  double least = distance2(best);
  for (int k = 0; k < cell.count; ++k) {
    const Vec3& p = cell.v[static_cast<std::size_t>(k)];
    const Vec3 middle = 0.5 * (p + cell.v[static_cast<std::size_t>((k + 1) % cell.count)]);
    for (const Vec3& candidate : {p, middle}) {
      const double d = distance2(candidate);
      if (d < least) least = d, best = candidate;
    }
  }
  return best;
}

void NearEdges::strips(const SourcePanel& cell, int edge, std::vector<SourcePanel>& out) const {
  const Edge& e = edges_[static_cast<std::size_t>(edge)];
  const Extent x = extentOf(cell, e);
  const double off = offAcross(x, e);
  const double margin = 1e-9 * (x.t1 - x.t0);
  const double margin2 = margin * margin;
  ConvexPolygon whole, sides[2], nearer, rest;
  whole.assign(cell);
  // The two sides of the edge's line, each cut from the line outwards (side 1 with the coordinate's sign
  // turned).
  int count = 0;
  if (x.t0 < -margin && x.t1 > margin) {
    if (splitByPlane(whole, e.a, e.across, margin2, sides[0], &sides[1]) != 0) sides[0] = whole;
    count = 2;
  } else {
    sides[0] = whole;
    count = 1;
  }
  for (int side = 0; side < count; ++side) {
    const double sign = (side == 1 || (count == 1 && x.t1 <= margin)) ? -1.0 : 1.0;
    const double from = sign > 0 ? std::max(0.0, x.t0) : std::max(0.0, -x.t1);
    const double to = sign > 0 ? x.t1 : -x.t0;
    ConvexPolygon* piece = &sides[side];
    double a = from;
    for (int k = 0; k < kMaxStrips && piece->count >= 3; ++k) {
      const double b = a + std::sqrt(a * a + off * off);
      if (b >= to - margin) break;
      // The part nearer the line than b, behind the plane whose normal points away from it.
      const Vec3 normal = sign * e.across;
      const Vec3 origin = e.a + (sign * b) * e.across;
      if (splitByPlane(*piece, origin, normal, margin2, rest, &nearer) == 0) {
        appendPanels(nearer, out);
        *piece = rest;
      }
      a = b;
    }
    if (piece->count >= 3) appendPanels(*piece, out);
  }
}

}  // namespace rt
