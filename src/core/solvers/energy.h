// Power bookkeeping of a radiosity solution, per RGB channel, in W (W/m^2 times the area unit squared).
// At the exact solution of B = E + rho F B: emitted = absorbed + escaped, which the tests check to 1e-9.
#pragma once

#include "core/solvers/radiosity_system.h"

namespace rt {

// Irradiance arriving at each element: H_j = (1/A_j) sum_i B_i A_i F_ij (uses the rows of F, not
// reciprocity).
RgbField incidentIrradiance(const RadiositySystem& system, const RgbField& B);
// sum_i E_i A_i.
Rgb emittedPower(const RadiositySystem& system);
// sum_j (1 - rho_j) H_j A_j: what the surfaces absorb of the light that arrives at them.
Rgb absorbedPower(const RadiositySystem& system, const RgbField& B);
// sum_i B_i A_i (1 - sum_j F_ij): what leaves the scene through its openings.
Rgb escapedPower(const RadiositySystem& system, const RgbField& B);
// sum_i X_i A_i per channel (X an RgbField of radiosities, e.g. the unshot radiosity).
Rgb powerOf(const RgbField& X, const Eigen::VectorXd& areas);

}  // namespace rt
