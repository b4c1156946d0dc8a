#include "viz/vertex_interpolation.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace rt::viz {
namespace {

constexpr double kPi = 3.14159265358979323846;

double sceneScale(const Mesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  return box.isEmpty() ? 1.0 : std::max(box.diagonal().norm(), 1e-12);
}

bool sameSmoothSurface(const Mesh& mesh, int a, int b, double tolerance) {
  if (a == b) return true;
  const Element& ea = mesh.elements[a];
  const Element& eb = mesh.elements[b];
  const bool sameMaterial =
      (mesh.reflectance.row(a) - mesh.reflectance.row(b)).cwiseAbs().maxCoeff() < 1e-12 &&
      (mesh.emission.row(a) - mesh.emission.row(b)).cwiseAbs().maxCoeff() < 1e-12;
  if (!sameMaterial) return false;
  if (ea.patch == eb.patch) return true;
  // Within about a degree and a small fraction of the scene: a measured wall split into two triangles because
  // it was slightly non-planar (the Cornell box's left wall) still shades as one surface.
  return ea.normal.dot(eb.normal) > 1.0 - 1.5e-4 &&
         std::abs(ea.normal.dot(eb.centroid - ea.centroid)) < tolerance;
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

double cornerAngle(const Mesh& mesh, const Element& e, std::size_t k) {
  const std::size_t m = e.vertices.size();
  const Vec3& p = mesh.vertices[e.vertices[k]];
  const Vec3 a = mesh.vertices[e.vertices[(k + m - 1) % m]] - p;
  const Vec3 b = mesh.vertices[e.vertices[(k + 1) % m]] - p;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

struct TVertex {
  int a = -1, b = -1;  // endpoints of the long edge
  double t = 0;        // position along it
};

}  // namespace

std::vector<int> smoothRegions(const Mesh& mesh) {
  const int n = static_cast<int>(mesh.size());
  const double tolerance = 2e-3 * sceneScale(mesh);
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& around : mesh.vertexElements)
    for (std::size_t i = 1; i < around.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (sameSmoothSurface(mesh, around[i], around[j], tolerance))
          parent[findRoot(parent, around[i])] = findRoot(parent, around[j]);
  std::vector<int> label(static_cast<std::size_t>(n), -1);
  std::map<int, int> relabel;
  for (int e = 0; e < n; ++e)
    label[e] = relabel.emplace(findRoot(parent, e), static_cast<int>(relabel.size())).first->second;
  return label;
}

CornerField flatCornerValues(const Mesh& mesh, const RgbField& perElement) {
  CornerField field;
  field.firstCorner.assign(mesh.size() + 1, 0);
  for (std::size_t e = 0; e < mesh.size(); ++e)
    field.firstCorner[e + 1] = field.firstCorner[e] + static_cast<int>(mesh.elements[e].vertices.size());
  field.values.resize(field.firstCorner.back(), 3);
  for (std::size_t e = 0; e < mesh.size(); ++e)
    for (int k = field.firstCorner[e]; k < field.firstCorner[e + 1]; ++k)
      field.values.row(k) = perElement.row(e);
  return field;
}

CornerField smoothCornerValues(const Mesh& mesh, const RgbField& perElement) {
  CornerField field = flatCornerValues(mesh, perElement);
  const std::vector<int> region = smoothRegions(mesh);
  const double tolerance = 1e-6 * sceneScale(mesh);

  // Per (region, vertex): angle covered by the region's elements and the elements cornered there.
  using Key = std::pair<int, int>;  // region, vertex
  std::map<Key, double> angle;
  std::map<Key, std::vector<int>> cornered;
  std::map<std::pair<int, std::pair<int, int>>, int> edgeUse;  // region, sorted edge -> count
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& el = mesh.elements[e];
    const std::size_t m = el.vertices.size();
    for (std::size_t k = 0; k < m; ++k) {
      const Key key{region[e], el.vertices[k]};
      angle[key] += cornerAngle(mesh, el, k);
      cornered[key].push_back(static_cast<int>(e));
      const int a = el.vertices[k], b = el.vertices[(k + 1) % m];
      ++edgeUse[{region[e], {std::min(a, b), std::max(a, b)}}];
    }
  }
  // T-vertices: a vertex of the region that lies strictly inside a boundary edge of the same region. Both
  // only occur on edges used once, so only those are searched.
  std::map<Key, TVertex> tVertices;
  std::map<int, std::vector<std::pair<int, int>>> openEdges;
  for (const auto& [key, count] : edgeUse)
    if (count == 1) openEdges[key.first].push_back(key.second);
  for (auto& [key, covered] : angle) {
    if (covered > 2 * kPi - 1e-6) continue;
    const Vec3& p = mesh.vertices[key.second];
    for (const auto& [a, b] : openEdges[key.first]) {
      if (a == key.second || b == key.second) continue;
      const Vec3 ab = mesh.vertices[b] - mesh.vertices[a];
      const double t = ab.dot(p - mesh.vertices[a]) / ab.squaredNorm();
      if (t <= 1e-9 || t >= 1 - 1e-9) continue;
      if ((mesh.vertices[a] + t * ab - p).norm() > tolerance) continue;
      tVertices[key] = {a, b, t};
      covered += kPi;  // the larger element covers the other half-plane
      break;
    }
  }
  auto interior = [&](const Key& key) { return angle[key] > 2 * kPi - 1e-6; };

  // Interior vertices: plain average of the elements around them.
  std::map<Key, Rgb> value;
  for (const auto& [key, elements] : cornered) {
    if (!interior(key)) continue;
    Rgb sum = Rgb::Zero();
    for (int e : elements) sum += perElement.row(e).transpose().array();
    value[key] = sum / static_cast<double>(elements.size());
  }
  // Boundary vertices: extrapolated through each element around them, B_e + g_e . (v - c_e), with g_e the
  // least-squares gradient from the centroids of e's neighbours in the region. On a regular grid this is the
  // classic 2 B_e - B_interior of the book; in general it is exact for a linear field on any mesh.
  std::map<int, Eigen::Matrix3Xd> gradient;  // element -> 3 x 3 (one column per channel)
  auto gradientOf = [&](int e) -> const Eigen::Matrix3Xd& {
    auto found = gradient.find(e);
    if (found != gradient.end()) return found->second;
    std::vector<int> neighbours;
    for (int v : mesh.elements[e].vertices)
      for (int other : mesh.vertexElements[v])
        if (other != e && region[other] == region[e] &&
            std::find(neighbours.begin(), neighbours.end(), other) == neighbours.end())
          neighbours.push_back(other);
    Eigen::Matrix3Xd g = Eigen::Matrix3Xd::Zero(3, 3);
    if (!neighbours.empty()) {
      Eigen::MatrixXd A(static_cast<Eigen::Index>(neighbours.size()), 3), b(A.rows(), 3);
      for (Eigen::Index k = 0; k < A.rows(); ++k) {
        A.row(k) = (mesh.elements[neighbours[k]].centroid - mesh.elements[e].centroid).transpose();
        b.row(k) = perElement.row(neighbours[k]) - perElement.row(e);
      }
      // Minimum-norm solution: no gradient along the normal, and none across a strip one element wide.
      g = A.completeOrthogonalDecomposition().solve(b);
    }
    return gradient.emplace(e, g).first->second;
  };
  for (const auto& [key, elements] : cornered) {
    if (interior(key)) continue;
    Rgb sum = Rgb::Zero();
    for (int e : elements) {
      const Vec3 offset = mesh.vertices[key.second] - mesh.elements[e].centroid;
      const Rgb extrapolated =
          perElement.row(e).transpose().array() + (gradientOf(e).transpose() * offset).array();
      sum += extrapolated.max(0.0);
    }
    value[key] = sum / static_cast<double>(elements.size());
  }
  // T-vertices last: along the long edge (twice, for T-vertices whose edge ends at another T-vertex).
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& [key, tv] : tVertices)
      value[key] = (1 - tv.t) * value[{key.first, tv.a}] + tv.t * value[{key.first, tv.b}];

  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& el = mesh.elements[e];
    for (std::size_t k = 0; k < el.vertices.size(); ++k)
      field.values.row(field.firstCorner[e] + static_cast<int>(k)) =
          value[{region[e], el.vertices[k]}].transpose();
  }
  return field;
}

}  // namespace rt::viz
