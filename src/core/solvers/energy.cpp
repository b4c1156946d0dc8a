#include "core/solvers/energy.h"

namespace rt {

RgbField incidentIrradiance(const RadiositySystem& system, const RgbField& B) {
  const FormFactorMatrix& F = *system.F;
  const RgbField leaving = system.areas.asDiagonal() * B;  // B_i A_i
  RgbField arriving = F.transpose() * leaving;             // sum_i B_i A_i F_ij
  for (Eigen::Index j = 0; j < arriving.rows(); ++j) {
    const double a = system.areas(j);
    arriving.row(j) = a > 0 ? (arriving.row(j) / a).eval() : Eigen::RowVector3d::Zero().eval();
  }
  return arriving;
}

Rgb powerOf(const RgbField& X, const Eigen::VectorXd& areas) {
  return (X.transpose() * areas).array();
}

Rgb emittedPower(const RadiositySystem& system) {
  return powerOf(system.emission, system.areas);
}

Rgb absorbedPower(const RadiositySystem& system, const RgbField& B) {
  const RgbField H = incidentIrradiance(system, B);
  const RgbField absorbed = ((1.0 - system.reflectance.array()) * H.array()).matrix();
  return powerOf(absorbed, system.areas);
}

Rgb escapedPower(const RadiositySystem& system, const RgbField& B) {
  const Eigen::VectorXd openFraction = (1.0 - system.F->rowwise().sum().array()).matrix();
  const Eigen::VectorXd weights = (system.areas.array() * openFraction.array()).matrix();
  return (B.transpose() * weights).array();
}

}  // namespace rt
