// A solved radiosity function on a mesh, constant per element or linear (linear_basis.h), evaluated
// anywhere on the mesh's patches, and the area-weighted difference of two such functions: how the error of
// a basis is measured against an exact function or a fine reference, point by point, never by element
// averages alone (which would hide what the basis draws between the nodes).
#pragma once

#include <functional>

#include "core/basis/linear_basis.h"

namespace rt {

// Holds pointers: the mesh, the basis and the values must outlive the field.
class RadiosityField {
 public:
  // Constant: one value per element (n x 3).
  RadiosityField(const Mesh& mesh, const RgbField& perElement);
  // Linear: one value per node of `basis` (m x 3).
  RadiosityField(const Mesh& mesh, const LinearBasis& basis, const RgbField& nodal);

  const Mesh& mesh() const { return *mesh_; }
  // The value at (u, v) of element e (ElementMap's parametrisation).
  Rgb at(int element, double u, double v) const;
  // The value at a point of patch `patch`: in the element of that patch that contains it (the nearest
  // when rounding puts it on none).
  Rgb at(const Vec3& point, int patch) const;

 private:
  const Mesh* mesh_;
  const LinearBasis* basis_ = nullptr;
  const RgbField* values_;
  std::vector<std::vector<int>> patchElements_;
};

// The point of element e at which the map reaches `point` (clamped to the unit square), and how far from
// `point` that lands.
struct ElementCoordinates {
  double u = 0, v = 0, distance = 0;
};
ElementCoordinates elementCoordinates(const Mesh& mesh, int element, const Vec3& point);

// int |f - g| dA / int |g| dA over the patches `include` accepts (all when empty), the mean of the three
// channels' integrals: `g` evaluated at the Gauss points (order a side) of f's elements.
double relativeL1Difference(const RadiosityField& f, const std::function<Rgb(const Vec3&, int patch)>& g,
                            int order, const std::function<bool(int patch)>& include = {});
// The same against a reference field, integrated over the reference's (finer) elements.
double relativeL1Difference(const RadiosityField& f, const RadiosityField& reference, int order,
                            const std::function<bool(int patch)>& include = {});

}  // namespace rt
