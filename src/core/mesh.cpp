#include "core/mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/polygon.h"

namespace rt {
namespace {

// Merges coincident vertices (within a tolerance relative to the scene size) so that elements of the same
// patch and of abutting patches share them.
class VertexWelder {
 public:
  VertexWelder(std::vector<Vec3>& vertices, double cell) : vertices_(vertices), cell_(cell) {}

  int add(const Vec3& p) {
    const auto key = keyOf(p);
    // Look in the neighbouring cells too, so points straddling a cell border still merge.
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find({std::get<0>(key) + dx, std::get<1>(key) + dy, std::get<2>(key) + dz});
          if (it == cells_.end()) continue;
          for (int index : it->second)
            if ((vertices_[index] - p).norm() <= cell_) return index;
        }
    const int index = static_cast<int>(vertices_.size());
    vertices_.push_back(p);
    cells_[key].push_back(index);
    return index;
  }

 private:
  using Key = std::tuple<long long, long long, long long>;
  Key keyOf(const Vec3& p) const {
    return {static_cast<long long>(std::floor(p.x() / cell_)),
            static_cast<long long>(std::floor(p.y() / cell_)),
            static_cast<long long>(std::floor(p.z() / cell_))};
  }
  std::vector<Vec3>& vertices_;
  double cell_;
  std::map<Key, std::vector<int>> cells_;
};

int divisionsFor(const Polygon& polygon, const MeshOptions& options) {
  switch (options.mode) {
    case MeshOptions::Mode::None:
      return 1;
    case MeshOptions::Mode::Count:
      return options.count;
    case MeshOptions::Mode::MaxEdge:
      return std::max(1, static_cast<int>(std::ceil(maxEdgeLength(polygon) / options.maxEdge - 1e-9)));
  }
  return 1;
}

// Bilinear N x N split of a convex quad: the sub-quads of a planar convex quad are planar and convex.
void splitQuad(const Polygon& q, int n, std::vector<Polygon>& out) {
  auto at = [&](int i, int j) {
    const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
    return Vec3((1 - u) * (1 - v) * q[0] + u * (1 - v) * q[1] + u * v * q[2] + (1 - u) * v * q[3]);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) out.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
}

// Barycentric split of a triangle into n^2 similar triangles.
void splitTriangle(const Polygon& t, int n, std::vector<Polygon>& out) {
  auto at = [&](int i, int j) {  // i along edge 0->1, j along edge 0->2
    return Vec3(t[0] + (t[1] - t[0]) * (static_cast<double>(i) / n) +
                (t[2] - t[0]) * (static_cast<double>(j) / n));
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i + j < n; ++i) {
      out.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + j + 1 < n) out.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
}

}  // namespace

Polygon Mesh::polygon(int element) const {
  Polygon p;
  for (int v : elements[element].vertices) p.push_back(vertices[v]);
  return p;
}

Eigen::VectorXd Mesh::areas() const {
  Eigen::VectorXd a(static_cast<Eigen::Index>(elements.size()));
  for (std::size_t i = 0; i < elements.size(); ++i) a[static_cast<Eigen::Index>(i)] = elements[i].area;
  return a;
}

std::vector<int> Mesh::edgeNeighbours(int element) const {
  std::vector<int> result;
  const auto& vs = elements[element].vertices;
  for (std::size_t k = 0; k < vs.size(); ++k) {
    const int a = vs[k], b = vs[(k + 1) % vs.size()];
    for (int other : vertexElements[a]) {
      if (other == element) continue;
      const auto& ov = elements[other].vertices;
      if (std::find(ov.begin(), ov.end(), b) != ov.end() &&
          std::find(result.begin(), result.end(), other) == result.end())
        result.push_back(other);
    }
  }
  return result;
}

std::uint64_t Mesh::geometryHash() const {
  // FNV-1a over the raw coordinates and the element connectivity.
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
  };
  for (const Vec3& v : vertices) mix(v.data(), sizeof(double) * 3);
  for (const Element& e : elements) {
    mix(e.vertices.data(), e.vertices.size() * sizeof(int));
    const int separator = -1;
    mix(&separator, sizeof separator);
  }
  return h;
}

Mesh buildMesh(const Scene& scene, const MeshOptions& options) {
  if (options.mode == MeshOptions::Mode::Count && options.count < 1)
    throw InputError({}, "--subdivide needs a count of at least 1, got " + std::to_string(options.count));
  if (options.mode == MeshOptions::Mode::MaxEdge &&
      !(options.maxEdge > 0.0 && std::isfinite(options.maxEdge)))
    throw InputError({}, "--max-edge needs a positive length");

  Mesh mesh;
  const Eigen::AlignedBox3d box = scene.bounds();
  const double size = box.isEmpty() ? 1.0 : std::max(box.diagonal().norm(), 1e-300);
  VertexWelder welder(mesh.vertices, 1e-9 * size);

  std::vector<Polygon> pieces;
  for (std::size_t p = 0; p < scene.patches.size(); ++p) {
    const Patch& patch = scene.patches[p];
    pieces.clear();
    const int n = divisionsFor(patch.vertices, options);
    if (patch.vertices.size() == 4) {
      splitQuad(patch.vertices, n, pieces);
    } else if (patch.vertices.size() == 3) {
      splitTriangle(patch.vertices, n, pieces);
    } else {
      for (const Polygon& t : fanTriangulate(patch.vertices))
        splitTriangle(t, divisionsFor(t, options), pieces);
    }
    for (const Polygon& piece : pieces) {
      Element e;
      e.patch = static_cast<int>(p);
      for (const Vec3& v : piece) e.vertices.push_back(welder.add(v));
      e.normal = patch.normal;
      e.area = polygonArea(piece);
      e.centroid = polygonCentroid(piece);
      mesh.elements.push_back(std::move(e));
    }
  }
  mesh.vertexElements.assign(mesh.vertices.size(), {});
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    for (int v : mesh.elements[e].vertices) mesh.vertexElements[v].push_back(static_cast<int>(e));
  refreshMaterials(mesh, scene);
  return mesh;
}

void refreshMaterials(Mesh& mesh, const Scene& scene) {
  const auto n = static_cast<Eigen::Index>(mesh.elements.size());
  mesh.reflectance.resize(n, 3);
  mesh.emission.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Material& m = scene.materialOfPatch(mesh.elements[i].patch);
    mesh.reflectance.row(i) = m.reflectance.matrix().transpose();
    mesh.emission.row(i) = m.emission.matrix().transpose();
  }
}

}  // namespace rt
