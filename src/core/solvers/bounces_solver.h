// The Neumann series B = sum_k (rho F)^k E, one bounce of light per iteration, every term kept: term 0 is the
// light emitted, term 1 the light after one reflection, and so on. Iteration k records the partial sum of
// terms 0..k, so a lesson can show the picture after k bounces and the energy carried by each bounce. The
// residual of the partial sum S_k is exactly ||term_{k+1}|| / ||E|| (K S_k - E = -(rho F)^{k+1} E).
#pragma once

#include <vector>

#include "core/solvers/solver.h"
#include "core/solvers/solver_support.h"

namespace rt {

// terms (optional): receives term 0 (= E), term 1, ..., term k for the last recorded iteration k.
SolverStatus neumannSeries(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                           const IterationSink& sink = {}, std::vector<RgbField>* terms = nullptr);

class BouncesSolver : public solver_detail::AlgorithmSolver {
 public:
  BouncesSolver();
  RgbField solve() override;
  // bounceTerms()[k] = (rho F)^k E; history()[k-1].B = sum of bounceTerms()[0..k].
  const std::vector<RgbField>& bounceTerms() const { return terms_; }

 private:
  std::vector<RgbField> terms_;
};

}  // namespace rt
