#include "core/basis/linear_basis.h"

#include <map>
#include <utility>

#include "core/formfactor/gauss_legendre.h"
#include "core/input_error.h"

namespace rt {

const std::vector<std::string>& basisNames() {
  static const std::vector<std::string> names{"constant", "linear"};
  return names;
}

std::optional<Basis> parseBasis(const std::string& name) {
  if (name == "constant") return Basis::Constant;
  if (name == "linear") return Basis::Linear;
  return std::nullopt;
}

std::string toString(Basis basis) {
  return basis == Basis::Linear ? "linear" : "constant";
}

ElementMap::ElementMap(const Mesh& mesh, int element) {
  const Element& e = mesh.elements[static_cast<std::size_t>(element)];
  count = static_cast<int>(e.vertices.size());
  for (int k = 0; k < count && k < 4; ++k) p[k] = mesh.vertices[static_cast<std::size_t>(e.vertices[k])];
}

void ElementMap::shape(double u, double v, double* phi) const {
  if (count == 3) {
    phi[0] = 1 - u;
    phi[1] = u * (1 - v);
    phi[2] = u * v;
    return;
  }
  phi[0] = (1 - u) * (1 - v);
  phi[1] = u * (1 - v);
  phi[2] = u * v;
  phi[3] = (1 - u) * v;
}

Vec3 ElementMap::point(double u, double v) const {
  double phi[4];
  shape(u, v, phi);
  Vec3 x = Vec3::Zero();
  for (int k = 0; k < count; ++k) x += phi[k] * p[k];
  return x;
}

double ElementMap::jacobian(double u, double v) const {
  if (count == 3) return u * (p[1] - p[0]).cross(p[2] - p[1]).norm();
  const Vec3 du = (1 - v) * (p[1] - p[0]) + v * (p[2] - p[3]);
  const Vec3 dv = (1 - u) * (p[3] - p[0]) + u * (p[2] - p[1]);
  return du.cross(dv).norm();
}

LinearBasis buildLinearBasis(const Mesh& mesh) {
  LinearBasis basis;
  std::map<std::pair<int, int>, int> nodeOf;  // (vertex, patch) -> node
  basis.firstCorner.assign(mesh.size() + 1, 0);
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& element = mesh.elements[e];
    const std::size_t corners = element.vertices.size();
    if (corners < 3 || corners > 4)
      throw InputError({}, "element " + std::to_string(e) + " of patch " + std::to_string(element.patch) +
                               " has " + std::to_string(corners) +
                               " corners: the linear basis needs triangles or quadrilaterals (mesh the "
                               "scene with a subdivision or a maximum edge)");
    for (const int vertex : element.vertices) {
      const auto [it, added] = nodeOf.try_emplace({vertex, element.patch}, static_cast<int>(basis.size()));
      if (added) {
        basis.nodeVertex.push_back(vertex);
        basis.nodePatch.push_back(element.patch);
      }
      basis.cornerNode.push_back(it->second);
    }
    basis.firstCorner[e + 1] = static_cast<int>(basis.cornerNode.size());
  }
  const auto m = static_cast<Eigen::Index>(basis.size());
  basis.weights = Eigen::VectorXd::Zero(m);
  basis.reflectance = RgbField::Zero(m, 3);
  basis.emission = RgbField::Zero(m, 3);
  basis.cornerWeight.assign(basis.cornerNode.size(), 0.0);
  // Shape function times Jacobian is of degree 2 in u and 1 in v: two Gauss points per direction are exact.
  const QuadratureRule& rule = gaussLegendre(2);
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const ElementMap map(mesh, static_cast<int>(e));
    for (std::size_t a = 0; a < rule.nodes.size(); ++a)
      for (std::size_t b = 0; b < rule.nodes.size(); ++b) {
        double phi[4];
        map.shape(rule.nodes[a], rule.nodes[b], phi);
        const double w = rule.weights[a] * rule.weights[b] * map.jacobian(rule.nodes[a], rule.nodes[b]);
        for (int k = 0; k < map.count; ++k)
          basis.cornerWeight[static_cast<std::size_t>(basis.firstCorner[e] + k)] += w * phi[k];
      }
    const auto row = static_cast<Eigen::Index>(e);
    for (int k = 0; k < map.count; ++k) {
      const auto corner = static_cast<std::size_t>(basis.firstCorner[e] + k);
      const auto node = static_cast<Eigen::Index>(basis.cornerNode[corner]);
      basis.weights[node] += basis.cornerWeight[corner];
      // Every element of a patch carries the patch's material (a mesh built without one has none).
      if (row < mesh.reflectance.rows()) basis.reflectance.row(node) = mesh.reflectance.row(row);
      if (row < mesh.emission.rows()) basis.emission.row(node) = mesh.emission.row(row);
    }
  }
  return basis;
}

RgbField LinearBasis::elementAverages(const RgbField& nodal) const {
  const auto n = static_cast<Eigen::Index>(firstCorner.size() - 1);
  RgbField out = RgbField::Zero(n, 3);
  for (Eigen::Index e = 0; e < n; ++e) {
    double area = 0;
    for (int c = firstCorner[static_cast<std::size_t>(e)]; c < firstCorner[static_cast<std::size_t>(e) + 1];
         ++c) {
      const double w = cornerWeight[static_cast<std::size_t>(c)];
      out.row(e) += w * nodal.row(cornerNode[static_cast<std::size_t>(c)]);
      area += w;
    }
    if (area > 0) out.row(e) /= area;
  }
  return out;
}

RgbField LinearBasis::cornerValues(const RgbField& nodal) const {
  RgbField out(static_cast<Eigen::Index>(cornerNode.size()), 3);
  for (std::size_t c = 0; c < cornerNode.size(); ++c)
    out.row(static_cast<Eigen::Index>(c)) = nodal.row(cornerNode[c]);
  return out;
}

Rgb LinearBasis::valueAt(const Mesh& mesh, const RgbField& nodal, int element, double u, double v) const {
  const ElementMap map(mesh, element);
  double phi[4];
  map.shape(u, v, phi);
  Rgb value = Rgb::Zero();
  for (int k = 0; k < map.count; ++k)
    value +=
        phi[k] *
        nodal.row(cornerNode[static_cast<std::size_t>(firstCorner[static_cast<std::size_t>(element)] + k)])
            .transpose()
            .array();
  return value;
}

}  // namespace rt
