// Power balance of a refined solution of a closed scene: everything emitted is absorbed.
#pragma once

#include <Eigen/Core>

#include "core/refine/refine.h"

namespace rt::test {

// absorbed / emitted per channel. With irradiance H = (B - E) / rho (every surface reflects something),
// sum E A = sum (1 - rho) H A.
inline Eigen::Array3d absorbedOverEmitted(const RefinedSolution& s) {
  const Eigen::VectorXd A = s.mesh.areas();
  Eigen::Array3d emitted = Eigen::Array3d::Zero(), absorbed = Eigen::Array3d::Zero();
  for (Eigen::Index i = 0; i < A.size(); ++i) {
    const Eigen::Array3d rho = s.mesh.reflectance.row(i).transpose().array();
    const Eigen::Array3d E = s.mesh.emission.row(i).transpose().array();
    const Eigen::Array3d H = (s.B.row(i).transpose().array() - E) / rho;
    emitted += A[i] * E;
    absorbed += A[i] * (1 - rho) * H;
  }
  return absorbed / emitted;
}

}  // namespace rt::test
