#include "core/formfactor/quadrature/solid_silhouette.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/formfactor/quadrature/closed_solids.h"
#include "core/geometry/small_buffer.h"

namespace rt {
namespace {

using Key = CornerKey::Key;

}  // namespace

std::vector<SolidShape> solidShapes(const std::vector<const std::vector<Vec3>*>& outlines,
                                    const std::vector<int>& solidOf, int solidCount) {
  std::vector<SolidShape> shapes(static_cast<std::size_t>(std::max(0, solidCount)));
  const CornerKey key(outlines);
  std::vector<std::map<Key, int>> cornerIndex(shapes.size());
  std::vector<std::map<std::pair<int, int>, int>> edgeOwner(shapes.size());  // directed edge -> face
  for (std::size_t k = 0; k < outlines.size() && k < solidOf.size(); ++k) {
    if (solidOf[k] < 0 || solidOf[k] >= solidCount) continue;
    const std::size_t s = static_cast<std::size_t>(solidOf[k]);
    SolidShape& shape = shapes[s];
    const std::vector<Vec3>& outline = *outlines[k];
    std::vector<int> face;
    Vec3 n = Vec3::Zero();
    for (std::size_t v = 0; v < outline.size(); ++v) {
      n += outline[v].cross(outline[(v + 1) % outline.size()]);
      const auto [it, added] =
          cornerIndex[s].emplace(key(outline[v]), static_cast<int>(shape.corners.size()));
      if (added) shape.corners.push_back(outline[v]);
      face.push_back(it->second);
    }
    n.normalize();
    const int f = static_cast<int>(shape.faces.size());
    shape.planes.push_back({n, n.dot(outline[0])});
    for (std::size_t v = 0; v < face.size(); ++v) edgeOwner[s][{face[v], face[(v + 1) % face.size()]}] = f;
    shape.faces.push_back(std::move(face));
  }
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    SolidShape& shape = shapes[s];
    for (const auto& [edge, face] : edgeOwner[s]) {
      if (edge.first > edge.second) continue;  // each edge once, from its lower corner
      const auto other = edgeOwner[s].find({edge.second, edge.first});
      if (other == edgeOwner[s].end()) continue;  // not closed: closedConvexSolids() would not have made it
      shape.edges.push_back({edge.first, edge.second, face, other->second});
    }
    for (const Vec3& c : shape.corners) shape.centre += c;
    if (!shape.corners.empty()) shape.centre /= static_cast<double>(shape.corners.size());
  }
  return shapes;
}

namespace {

// visit(a, b, n) for each silhouette edge from x (corners a, b; n the inward side plane). Returns their
// number: 0 when x is not outside the solid, -1 when `visit` refuses one (full).
template <class Visit>
int forEachSilhouetteEdge(const SolidShape& solid, const Vec3& x, double eps, Visit&& visit) {
  const int faceCount = static_cast<int>(solid.planes.size());
  // On the stack up to 64 faces; past that (a prism of many sides) in a per-thread array kept between calls,
  // as this runs once per clipped point.
  constexpr int kLocal = 64;
  bool local[kLocal];
  bool* front = local;
  if (faceCount > kLocal) {
    thread_local SmallBuffer<bool, 1> spilled;
    spilled.reserve(faceCount);
    front = spilled.data();
  }
  bool any = false;
  for (int f = 0; f < faceCount; ++f) {
    const auto& [n, offset] = solid.planes[static_cast<std::size_t>(f)];
    front[f] = n.dot(x) - offset > eps;  // a face seen edge-on counts as seen from behind: it hides no area
    any |= front[f];
  }
  if (!any) return 0;
  const Vec3 inside = solid.centre - x;
  int count = 0;
  for (const SolidShape::Edge& edge : solid.edges) {
    if (front[edge.left] == front[edge.right]) continue;
    const Vec3 a = solid.corners[static_cast<std::size_t>(edge.a)] - x,
               b = solid.corners[static_cast<std::size_t>(edge.b)] - x;
    Vec3 n = a.cross(b);
    // End-on (x in line with the edge, to rounding): no plane of its own.
    if (!(n.squaredNorm() > 1e-24 * a.squaredNorm() * b.squaredNorm())) continue;
    if (n.dot(inside) < 0) n = -n;
    if (!visit(edge.a, edge.b, n)) return -1;
    ++count;
  }
  return count;
}

}  // namespace

int silhouetteEdges(const SolidShape& solid, const Vec3& x, double eps, SilhouetteEdge* out, int capacity) {
  int count = 0;
  return forEachSilhouetteEdge(solid, x, eps, [&](int a, int b, const Vec3& n) {
    if (count == capacity) return false;
    out[count++] = {n, a, b};
    return true;
  });
}

int silhouetteCone(const SolidShape& solid, const Vec3& x, double eps, Vec3* cone, int capacity) {
  int count = 0;
  return forEachSilhouetteEdge(solid, x, eps, [&](int, int, const Vec3& n) {
    if (count == capacity) return false;
    cone[count++] = n;
    return true;
  });
}

}  // namespace rt
