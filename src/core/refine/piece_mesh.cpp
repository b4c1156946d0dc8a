#include "core/refine/piece_mesh.h"

#include <algorithm>

#include "core/polygon.h"

namespace rt {

Mesh meshFromPieces(const Scene& scene, const std::vector<Polygon>& pieces,
                    const std::vector<int>& patchOfPiece) {
  // buildMesh already welds vertices and fills the element data: give it the pieces as patches, then point
  // the elements back at the real patches.
  Scene pieceScene;
  pieceScene.materials = scene.materials;
  pieceScene.surfaces = scene.surfaces;
  pieceScene.patches.reserve(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Patch& parent = scene.patches[patchOfPiece[k]];
    Patch p;
    p.vertices = pieces[k];
    p.normal = parent.normal;
    p.area = polygonArea(pieces[k]);
    p.surface = parent.surface;
    pieceScene.patches.push_back(std::move(p));
  }
  Mesh mesh = buildMesh(pieceScene);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) mesh.elements[e].patch = patchOfPiece[e];
  refreshMaterials(mesh, scene);
  return mesh;
}

std::vector<Polygon> splitInFour(const Polygon& p) {
  if (p.size() > 4) return fanTriangulate(p);  // an n-gon element (one element per patch): triangles first
  if (p.size() == 3) {
    const Vec3 m01 = 0.5 * (p[0] + p[1]), m12 = 0.5 * (p[1] + p[2]), m20 = 0.5 * (p[2] + p[0]);
    return {{p[0], m01, m20}, {m01, p[1], m12}, {m20, m12, p[2]}, {m01, m12, m20}};
  }
  const Vec3 m01 = 0.5 * (p[0] + p[1]), m12 = 0.5 * (p[1] + p[2]), m23 = 0.5 * (p[2] + p[3]),
             m30 = 0.5 * (p[3] + p[0]);
  const Vec3 c = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  return {{p[0], m01, c, m30}, {m01, p[1], m12, c}, {c, m12, p[2], m23}, {m30, c, m23, p[3]}};
}

std::vector<TVertex> findTVertices(const Mesh& mesh) {
  std::vector<TVertex> result;
  // Vertices used by each patch: a hanging vertex only matters for interpolation within its own patch.
  int patches = 0;
  for (const Element& e : mesh.elements) patches = std::max(patches, e.patch + 1);
  std::vector<std::vector<int>> patchVertices(patches);
  for (const Element& e : mesh.elements)
    for (int v : e.vertices) patchVertices[e.patch].push_back(v);
  for (auto& list : patchVertices) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& element = mesh.elements[e];
    const std::size_t n = element.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      const int a = element.vertices[k], b = element.vertices[(k + 1) % n];
      const Vec3& pa = mesh.vertices[a];
      const Vec3 d = mesh.vertices[b] - pa;
      const double len2 = d.squaredNorm();
      if (len2 <= 0) continue;
      for (int v : patchVertices[element.patch]) {
        if (v == a || v == b) continue;
        const Vec3 w = mesh.vertices[v] - pa;
        const double t = w.dot(d) / len2;
        if (t <= 1e-9 || t >= 1 - 1e-9) continue;
        if ((w - t * d).squaredNorm() > 1e-16 * len2) continue;
        result.push_back({v, static_cast<int>(e), a, b, t});
      }
    }
  }
  return result;
}

std::vector<std::vector<int>> smoothNeighbours(const Scene& scene, const Mesh& mesh,
                                               const std::vector<TVertex>& tVertices) {
  const std::size_t n = mesh.elements.size();
  std::vector<std::vector<int>> touching(n);
  auto sameSheet = [&](int a, int b) {
    const Element& ea = mesh.elements[a];
    const Element& eb = mesh.elements[b];
    if (ea.patch == eb.patch) return true;
    return scene.patches[ea.patch].surface == scene.patches[eb.patch].surface &&
           ea.normal.dot(eb.normal) > 0.999;
  };
  auto addAround = [&](int e, int v) {
    for (int other : mesh.vertexElements[v])
      if (other != e && sameSheet(e, other)) {
        touching[e].push_back(other);
        touching[other].push_back(e);
      }
  };
  for (std::size_t e = 0; e < n; ++e)
    for (int v : mesh.elements[e].vertices) addAround(static_cast<int>(e), v);
  for (const TVertex& t : tVertices) addAround(t.element, t.vertex);
  for (auto& list : touching) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return touching;
}

}  // namespace rt
