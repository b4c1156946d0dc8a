// The radiosity system B = E + diag(rho) F B, per RGB channel, with everything a solver needs.
#pragma once

#include "core/formfactor/formfactor_matrix.h"
#include "core/mesh.h"
#include "core/vec.h"

namespace rt {

struct RadiositySystem {
  const FormFactorMatrix* F = nullptr;  // n x n, not owned (shared by the three channels)
  // The elements themselves, not owned: solvers that trace rays (local-lines) need it, and then F may be
  // null. Systems built from a matrix alone have no geometry.
  const Mesh* mesh = nullptr;
  RgbField reflectance;   // n x 3
  RgbField emission;      // n x 3
  Eigen::VectorXd areas;  // n

  std::size_t size() const { return static_cast<std::size_t>(areas.size()); }
  static RadiositySystem fromMesh(const Mesh& mesh, const FormFactorMatrix& F);
  // The same without form factors, for the solvers that never store one.
  static RadiositySystem fromGeometry(const Mesh& mesh);
  // ||K B - E|| / ||E|| over all channels (Frobenius), K = I - diag(rho) F. Without F it cannot be
  // computed: NaN.
  double relativeResidual(const RgbField& B) const;
  // The same with F B given (a solver that has the product at hand saves the pass over F).
  double relativeResidual(const RgbField& B, const RgbField& FB) const;
};

}  // namespace rt
