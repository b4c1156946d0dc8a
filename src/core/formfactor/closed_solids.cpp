#include "core/formfactor/closed_solids.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

namespace rt {
namespace {

using Key = std::tuple<long long, long long, long long>;

int findRoot(std::vector<int>& parent, int k) {
  while (parent[static_cast<std::size_t>(k)] != k)
    k = parent[static_cast<std::size_t>(k)] =
        parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(k)])];
  return k;
}

}  // namespace

std::vector<int> closedConvexSolids(const std::vector<const std::vector<Vec3>*>& outlines,
                                    std::vector<SolidPlanes>& planes) {
  const std::size_t P = outlines.size();
  std::vector<int> solid(P, -1);
  planes.clear();
  double size = 0;
  for (const auto* outline : outlines)
    for (const Vec3& v : *outline) size = std::max(size, v.cwiseAbs().maxCoeff());
  if (!(size > 0)) return solid;
  // Corners that agree to 1e-9 of the scene's size are the same corner.
  const double quantum = 1e-9 * size;
  auto key = [&](const Vec3& v) {
    return Key{std::llround(v.x() / quantum), std::llround(v.y() / quantum), std::llround(v.z() / quantum)};
  };
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
      Vec3 n = Vec3::Zero();
      for (std::size_t v = 0; v < outline.size(); ++v)
        n += outline[v].cross(outline[(v + 1) % outline.size()]);
      n.normalize();
      faces.push_back({n, n.dot(outline[0])});
    }
    bool convex = true;
    for (int k : members)
      for (const Vec3& v : *outlines[static_cast<std::size_t>(k)])
        for (const auto& [n, offset] : faces) convex = convex && n.dot(v) - offset <= 1e-9 * size;
    if (!convex) continue;
    for (int k : members) solid[static_cast<std::size_t>(k)] = static_cast<int>(planes.size());
    planes.push_back(std::move(faces));
  }
  return solid;
}

namespace {

// clipToFront, except that a polygon lying in the plane is kept whole by `behind` and dropped otherwise (the
// floor under a block lies in the plane of the block's bottom).
void clipSide(const SmallPolygon& in, const Vec3& n, double offset, double eps, bool behind,
              SmallPolygon& out) {
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

double areaInside(const SmallPolygon& polygon, const SolidPlanes& solid, double eps) {
  SmallPolygon inside = polygon, next;
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

void piecesOutside(const SmallPolygon& polygon, const SolidPlanes& solid, double eps,
                   std::vector<SmallPolygon>& out) {
  SmallPolygon inside = polygon, part;
  for (const auto& [n, offset] : solid) {
    clipSide(inside, n, offset, eps, false, part);
    if (part.count > 0) out.push_back(part);
    clipSide(inside, n, offset, eps, true, part);
    inside = part;
    if (inside.count == 0) return;
  }
}

}  // namespace rt
