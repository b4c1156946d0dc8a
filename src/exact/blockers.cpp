#include "exact/blockers.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/polygon.h"

namespace rt::exact {
namespace {

// The convex hull of coplanar points (the plane's unit normal `n`), counter-clockwise seen from the side n
// points to, by gift wrapping: each next corner is the point that leaves every other on its left. Points
// within `eps` of an edge's line are not corners.
Polygon coplanarHull(std::vector<Vec3> points, const Vec3& n, double eps) {
  // Neighbouring elements share their corners: each point once.
  std::sort(points.begin(), points.end(), [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return {};
  std::size_t start = 0;  // the lowest point along an in-plane axis is a corner
  const Vec3 axis = n.unitOrthogonal();
  for (std::size_t k = 1; k < points.size(); ++k)
    if (points[k].dot(axis) < points[start].dot(axis)) start = k;
  Polygon hull;
  std::size_t current = start;
  do {
    hull.push_back(points[current]);
    std::size_t next = current == 0 ? 1 : 0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (k == current) continue;
      const Vec3 edge = points[next] - points[current], to = points[k] - points[current];
      const double side = n.dot(edge.cross(to));  // > 0: k is left of current -> next
      const double length = edge.norm();
      // k right of the edge, or on its line and farther: k replaces next.
      if (side < -eps * length || (std::abs(side) <= eps * length && to.squaredNorm() > edge.squaredNorm()))
        next = k;
    }
    current = next;
  } while (current != start && hull.size() <= points.size());
  return hull.size() >= 3 ? hull : Polygon{};
}

// Every corner of `inner` on or inside the convex `outer` (counter-clockwise about its unit normal n),
// within eps.
bool inside(const Polygon& inner, const Polygon& outer, const Vec3& n, double eps) {
  for (std::size_t k = 0; k < outer.size(); ++k) {
    const Vec3 edge = outer[(k + 1) % outer.size()] - outer[k];
    const Vec3 inward = n.cross(edge).normalized();
    for (const Vec3& v : inner)
      if (inward.dot(v - outer[k]) < -eps) return false;
  }
  return true;
}

}  // namespace

std::vector<Polygon> mergeOccluders(const Mesh& mesh, const std::vector<int>& occluders,
                                    const std::vector<Polygon>& polygons, double eps) {
  std::map<int, std::vector<std::size_t>> byPatch;
  for (std::size_t k = 0; k < occluders.size(); ++k)
    byPatch[mesh.elements[static_cast<std::size_t>(occluders[k])].patch].push_back(k);
  std::vector<Polygon> merged;
  std::vector<Vec3> normals;
  for (const auto& [patch, members] : byPatch) {
    const Vec3 n = mesh.elements[static_cast<std::size_t>(occluders[members.front()])].normal.normalized();
    if (members.size() == 1 || patch < 0) {
      for (std::size_t k : members) {
        merged.push_back(polygons[k]);
        normals.push_back(mesh.elements[static_cast<std::size_t>(occluders[k])].normal.normalized());
      }
      continue;
    }
    std::vector<Vec3> corners;
    for (std::size_t k : members) corners.insert(corners.end(), polygons[k].begin(), polygons[k].end());
    merged.push_back(coplanarHull(std::move(corners), n, eps));
    normals.push_back(n);
  }
  // Coplanar polygons (either orientation) inside another: left out, the first of two equal ones kept.
  std::vector<bool> drop(merged.size(), false);
  for (std::size_t a = 0; a < merged.size(); ++a) {
    if (merged[a].size() < 3) {
      drop[a] = true;
      continue;
    }
    for (std::size_t b = 0; b < merged.size() && !drop[a]; ++b) {
      if (a == b || drop[b] || merged[b].size() < 3) continue;
      const Vec3& n = normals[b];
      if (std::abs(std::abs(n.dot(normals[a])) - 1) > 1e-12) continue;
      if (std::abs(n.dot(merged[a].front() - merged[b].front())) > eps) continue;
      if (inside(merged[a], merged[b], n, eps) && (b < a || !inside(merged[b], merged[a], n, eps)))
        drop[a] = true;
    }
  }
  std::vector<Polygon> out;
  for (std::size_t k = 0; k < merged.size(); ++k)
    if (!drop[k]) out.push_back(std::move(merged[k]));
  return out;
}

}  // namespace rt::exact
