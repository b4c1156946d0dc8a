#include "core/formfactor/quadrature/closed_solids.h"
#include "core/geometry/plane_clip.h"
#include "core/polygon.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

namespace rt {
namespace {

using Key = CornerKey::Key;

int findRoot(std::vector<int>& parent, int k) {
  while (parent[static_cast<std::size_t>(k)] != k)
    k = parent[static_cast<std::size_t>(k)] =
        parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(k)])];
  return k;
}

}  // namespace

CornerKey::CornerKey(const std::vector<const std::vector<Vec3>*>& outlines) {
  for (const auto* outline : outlines)
    for (const Vec3& v : *outline) size_ = std::max(size_, v.cwiseAbs().maxCoeff());
  quantum_ = 1e-9 * std::max(size_, 1e-300);
}

std::vector<int> closedConvexSolids(const std::vector<const std::vector<Vec3>*>& outlines,
                                    std::vector<SolidPlanes>& planes) {
  const std::size_t P = outlines.size();
  std::vector<int> solid(P, -1);
  planes.clear();
  const CornerKey key(outlines);
  const double size = key.size();
  if (!(size > 0)) return solid;
  // Directed edge -> how many patches use it.
  std::map<std::pair<Key, Key>, int> edges;
  for (const auto* outline : outlines)
    for (std::size_t v = 0; v < outline->size(); ++v)
      ++edges[{key((*outline)[v]), key((*outline)[(v + 1) % outline->size()])}];
  std::vector<int> parent(P);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<bool> closed(P, true);
  std::map<std::pair<Key, Key>, int> owner;
  for (std::size_t k = 0; k < P; ++k) {
    const auto& outline = *outlines[k];
    closed[k] = outline.size() >= 3;
    for (std::size_t v = 0; v < outline.size(); ++v) {
      const Key a = key(outline[v]), b = key(outline[(v + 1) % outline.size()]);
      owner[{a, b}] = static_cast<int>(k);
      const auto reverse = edges.find({b, a});
      if (edges[{a, b}] != 1 || reverse == edges.end() || reverse->second != 1) closed[k] = false;
    }
  }
  for (std::size_t k = 0; k < P; ++k) {
    const auto& outline = *outlines[k];
    for (std::size_t v = 0; v < outline.size(); ++v) {
      const auto other = owner.find({key(outline[(v + 1) % outline.size()]), key(outline[v])});
      if (other != owner.end())
        parent[static_cast<std::size_t>(findRoot(parent, static_cast<int>(k)))] =
            findRoot(parent, other->second);
    }
  }
  std::map<int, std::vector<int>> groups;
  for (std::size_t k = 0; k < P; ++k)
    groups[findRoot(parent, static_cast<int>(k))].push_back(static_cast<int>(k));
  for (const auto& [root, members] : groups) {
    if (members.size() < 4) continue;
    if (!std::all_of(members.begin(), members.end(),
                     [&](int k) { return closed[static_cast<std::size_t>(k)]; }))
      continue;
    SolidPlanes faces;
    for (int k : members) {
      const auto& outline = *outlines[static_cast<std::size_t>(k)];
      const Vec3 n = newellNormal(outline).normalized();
      faces.push_back({n, n.dot(outline[0])});
    }
    // Every corner on or behind every face, and every face with a corner well behind it (some volume: faces
    // lying on one plane, a patch and the face closing it, would pass the first test). Each test stops at
    // its first failure: a closed room of thousands of inward-facing quads fails at once instead of testing
    // every corner against every face.
    // The group by a plain reference: clang 14, the fuzzers' compiler, cannot capture a structured binding.
    const std::vector<int>& group = members;
    auto convex = [&]() {
      for (const auto& [n, offset] : faces) {
        bool behind = false;
        for (int k : group)
          for (const Vec3& v : *outlines[static_cast<std::size_t>(k)]) {
            const double height = n.dot(v) - offset;
            if (height > 1e-9 * size) return false;
            behind = behind || height < -1e-6 * size;
          }
        if (!behind) return false;
      }
      return true;
    };
    if (!convex()) continue;
    for (int k : members) solid[static_cast<std::size_t>(k)] = static_cast<int>(planes.size());
    planes.push_back(std::move(faces));
  }
  return solid;
}

std::vector<std::vector<Vec3>> closingFaces(const std::vector<const std::vector<Vec3>*>& outlines) {
  std::vector<std::vector<Vec3>> faces;
  const std::size_t P = outlines.size();
  const CornerKey key(outlines);
  const double size = key.size();
  if (!(size > 0)) return faces;
  std::map<std::pair<Key, Key>, int> edges, owner;
  for (std::size_t k = 0; k < P; ++k)
    for (std::size_t v = 0; v < outlines[k]->size(); ++v) {
      const std::pair<Key, Key> edge{key((*outlines[k])[v]),
                                     key((*outlines[k])[(v + 1) % outlines[k]->size()])};
      ++edges[edge];
      owner[edge] = static_cast<int>(k);
    }
  std::vector<int> parent(P);
  std::iota(parent.begin(), parent.end(), 0);
  // Per group: its unshared edges, start -> (end, the start's position).
  for (const auto& [edge, count] : edges) {
    const auto reverse = owner.find({edge.second, edge.first});
    if (reverse != owner.end())
      parent[static_cast<std::size_t>(findRoot(parent, owner[edge]))] = findRoot(parent, reverse->second);
  }
  std::map<int, std::map<Key, std::pair<Key, Vec3>>> open;
  std::map<int, bool> broken;
  for (std::size_t k = 0; k < P; ++k)
    for (std::size_t v = 0; v < outlines[k]->size(); ++v) {
      const Vec3& a = (*outlines[k])[v];
      const Key ka = key(a), kb = key((*outlines[k])[(v + 1) % outlines[k]->size()]);
      if (edges.count({kb, ka})) continue;
      const int root = findRoot(parent, static_cast<int>(k));
      if (edges[{ka, kb}] != 1 || open[root].count(ka)) broken[root] = true;  // not a simple loop
      open[root][ka] = {kb, a};
    }
  for (const auto& [root, loop] : open) {
    if (broken[root] || loop.size() < 3) continue;
    // Walk the loop once; it must use every unshared edge.
    std::vector<Vec3> corners;
    Key at = loop.begin()->first;
    for (std::size_t step = 0; step < loop.size(); ++step) {
      const auto next = loop.find(at);
      if (next == loop.end()) break;
      corners.push_back(next->second.second);
      at = next->second.first;
    }
    if (corners.size() != loop.size() || at != loop.begin()->first) continue;
    // Planar: every corner on the plane of the loop's area vector.
    Vec3 n = newellNormal(corners);
    if (!(n.norm() > 0)) continue;
    n.normalize();
    bool planar = true;
    for (const Vec3& c : corners) planar = planar && std::abs(n.dot(c - corners[0])) <= 1e-9 * size;
    if (!planar) continue;
    std::reverse(corners.begin(), corners.end());
    faces.push_back(std::move(corners));
  }
  return faces;
}

namespace {

// clipToFront, except that a polygon lying in the plane is kept whole by `behind` and dropped otherwise (the
// floor under a block lies in the plane of the block's bottom).
void clipSide(const ConvexPolygon& in, const Vec3& n, double offset, double eps, bool behind,
              ConvexPolygon& out) {
  bool inPlane = true;
  for (int k = 0; k < in.count && inPlane; ++k)
    inPlane = std::abs(n.dot(in.v[static_cast<std::size_t>(k)]) - offset) <= eps;
  if (inPlane) {
    out = in;
    if (!behind) out.count = 0;
    return;
  }
  clipToFront(in.v.data(), in.count, n * offset, behind ? Vec3(-n) : n, eps, out);
}

}  // namespace

double areaInside(const ConvexPolygon& polygon, const SolidPlanes& solid, double eps) {
  ConvexPolygon inside = polygon, next;
  for (const auto& [n, offset] : solid) {
    clipSide(inside, n, offset, eps, true, next);
    inside = next;
    if (inside.count == 0) return 0;
  }
  Vec3 sum = Vec3::Zero();
  for (int k = 0; k < inside.count; ++k)
    sum += inside.v[static_cast<std::size_t>(k)].cross(
        inside.v[static_cast<std::size_t>((k + 1) % inside.count)]);
  return 0.5 * sum.norm();
}

void piecesOutside(const ConvexPolygon& polygon, const SolidPlanes& solid, double eps,
                   std::vector<ConvexPolygon>& out) {
  ConvexPolygon inside = polygon, part;
  for (const auto& [n, offset] : solid) {
    clipSide(inside, n, offset, eps, false, part);
    if (part.count > 0) out.push_back(part);
    clipSide(inside, n, offset, eps, true, part);
    inside = part;
    if (inside.count == 0) return;
  }
}

}  // namespace rt
