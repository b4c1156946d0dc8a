// The radiosity system B = E + diag(rho) F B, per RGB channel, with everything a solver needs.
#pragma once

#include "core/formfactor/formfactor_matrix.h"
#include "core/mesh.h"
#include "core/vec.h"

namespace rt {

struct RadiositySystem {
  const FormFactorMatrix* F = nullptr;  // n x n, not owned (shared by the three channels)
  RgbField reflectance;                 // n x 3
  RgbField emission;                    // n x 3
  Eigen::VectorXd areas;                // n

  std::size_t size() const { return static_cast<std::size_t>(areas.size()); }
  static RadiositySystem fromMesh(const Mesh& mesh, const FormFactorMatrix& F);
  // ||K B - E|| / ||E|| over all channels (Frobenius), K = I - diag(rho) F.
  double relativeResidual(const RgbField& B) const;
};

}  // namespace rt
