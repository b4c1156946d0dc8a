// The radiosity function's basis (Cohen & Wallace 1993, ch. 3): constant per element, the classic system
// B_i = E_i + rho_i sum_j F_ij B_j, or linear per element, continuous through the vertices an element shares
// with the others of its patch. A linear function is one value per node (a vertex of a patch: where two
// patches meet, each keeps its own node, so that creases, material and emission boundaries stay sharp);
// inside an element it is interpolated by the element's shape functions: barycentric coordinates on a
// triangle, bilinear ones on a quadrilateral.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/mesh.h"

namespace rt {

enum class Basis { Constant, Linear };
// "constant", "linear": the values of the `basis` setting.
const std::vector<std::string>& basisNames();
std::optional<Basis> parseBasis(const std::string& name);
std::string toString(Basis basis);

// An element as a map from the unit square (u, v) in [0,1]^2: a quadrilateral bilinearly, a triangle through
// the collapsed square (lambda_0 = 1 - u, lambda_1 = u (1 - v), lambda_2 = u v), whose Jacobian 2 A u
// vanishes at corner 0 so that a Gauss rule never samples the corner itself.
struct ElementMap {
  Vec3 p[4];
  int count = 0;  // 3 or 4
  ElementMap(const Mesh& mesh, int element);
  // The point at (u, v), its shape functions (count of them, summing to 1) and dA / du dv.
  Vec3 point(double u, double v) const;
  void shape(double u, double v, double* phi) const;
  double jacobian(double u, double v) const;
};

struct LinearBasis {
  std::vector<int> nodeVertex;  // per node: the mesh vertex it sits on
  std::vector<int> nodePatch;   // per node: the patch it belongs to
  // Corner k of element e is node cornerNode[firstCorner[e] + k] (the elements' own vertex order).
  std::vector<int> firstCorner;
  std::vector<int> cornerNode;
  std::vector<double> cornerWeight;  // the integral of the corner's shape function over its element
  // Per node: the integral of its basis function (the "area" of the node, with which power is counted), its
  // patch's reflectance and emission.
  Eigen::VectorXd weights;
  RgbField reflectance, emission;

  std::size_t size() const { return nodeVertex.size(); }
  // The element averages of a nodal field (n x 3): what a constant basis would hold.
  RgbField elementAverages(const RgbField& nodal) const;
  // The nodal field at every element corner, in the corner order above: the linear function itself, for
  // display (one value per corner; the element interpolates between them).
  RgbField cornerValues(const RgbField& nodal) const;
  // The field's value at (u, v) of element e (ElementMap's parametrisation).
  Rgb valueAt(const Mesh& mesh, const RgbField& nodal, int element, double u, double v) const;
};

// The nodes of a mesh of triangles and quadrilaterals. Throws InputError naming the element for an element
// of more than four corners (a patch kept whole: mesh it with a subdivision or a maximum edge).
LinearBasis buildLinearBasis(const Mesh& mesh);

}  // namespace rt
