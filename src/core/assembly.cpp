#include "core/assembly.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rt {

double fillFraction(const FormFactorMatrix& F) {
  if (F.size() == 0) return 0.0;
  return static_cast<double>((F.array() != 0.0).count()) / static_cast<double>(F.size());
}

Eigen::MatrixXd assembleDense(const FormFactorMatrix& F, const Eigen::VectorXd& rho) {
  // I - rho F rather than -(rho F) + I: zeros stay +0 (no "-0" in exported matrices).
  return Eigen::MatrixXd::Identity(F.rows(), F.cols()) - rho.asDiagonal() * F;
}

SparseRowMatrix assembleSparse(const FormFactorMatrix& F, const Eigen::VectorXd& rho) {
  const Eigen::Index n = F.rows();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>((F.array() != 0.0).count() + n));
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      const double k = (i == j ? 1.0 : 0.0) - rho(i) * F(i, j);
      if (k != 0.0) entries.emplace_back(static_cast<int>(i), static_cast<int>(j), k);
    }
  }
  SparseRowMatrix K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

Eigen::MatrixXd AssembledMatrix::toDense() const {
  return sparse ? Eigen::MatrixXd(sparseK) : dense;
}

AssembledMatrix assemble(const RadiositySystem& system, int channel, double sparseBelowFill) {
  AssembledMatrix m;
  m.channel = channel;
  m.fill = fillFraction(*system.F);
  m.sparse = m.fill < sparseBelowFill;
  const Eigen::VectorXd rho = system.reflectance.col(channel);
  if (m.sparse)
    m.sparseK = assembleSparse(*system.F, rho);
  else
    m.dense = assembleDense(*system.F, rho);
  return m;
}

SpectralRadiusEstimate spectralRadius(const FormFactorMatrix& F, const Eigen::VectorXd& rho,
                                      int maxIterations, double tolerance) {
  SpectralRadiusEstimate e;
  const Eigen::Index n = F.rows();
  if (n == 0) {
    e.converged = true;
    return e;
  }
  // A positive start vector has a component along the (non-negative) Perron vector.
  Eigen::VectorXd x = Eigen::VectorXd::Ones(n) / std::sqrt(static_cast<double>(n));
  // Nilpotent M (light that dies out after a few bounces: an open scene whose emitters reflect nothing) has
  // radius 0, which power iteration on M + I only approaches like 1/k. For M >= 0 and x > 0, M^k x = 0
  // exactly when M^k = 0, so a few plain products detect it (chains of up to 64 bounces).
  Eigen::VectorXd z = x;
  for (Eigen::Index k = 0; k < std::min<Eigen::Index>(n, 64); ++k) {
    z = rho.cwiseProduct(F * z);
    if (z.isZero(0.0)) {
      e.converged = true;
      e.iterations = static_cast<int>(k + 1);
      return e;
    }
  }
  double previous = std::numeric_limits<double>::infinity();
  for (int k = 1; k <= maxIterations; ++k) {
    const Eigen::VectorXd y = rho.cwiseProduct(F * x) + x;  // (M + I) x
    // Collatz-Wielandt: for x > 0, min_i and max_i of (Mx)_i / x_i bracket the spectral radius (the lower
    // bound needs M irreducible; with black elements it may stay at 0, so convergence is also judged on the
    // estimate).
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (x(i) <= 0.0) continue;
      const double ratio = y(i) / x(i);
      lo = std::min(lo, ratio);
      hi = std::max(hi, ratio);
    }
    const double norm = y.norm();
    e.iterations = k;
    e.lower = std::max(0.0, lo - 1.0);
    e.upper = std::max(0.0, hi - 1.0);
    e.value = std::clamp(norm - 1.0, e.lower, e.upper);  // ||(M+I)x|| with ||x|| = 1
    if (e.upper - e.lower <= tolerance * std::max(1.0, e.upper) ||
        std::abs(e.value - previous) <= tolerance * std::max(1.0, e.value)) {
      e.converged = true;
      break;
    }
    previous = e.value;
    if (!(norm > 0.0)) break;
    x = y / norm;
  }
  return e;
}

std::optional<double> conditionNumber(const Eigen::MatrixXd& K) {
  if (K.rows() > kMaxConditionSize || K.cols() > kMaxConditionSize) return std::nullopt;
  if (K.size() == 0) return 1.0;
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(K);
  const auto& s = svd.singularValues();
  const double smallest = s(s.size() - 1);
  if (!(smallest > 0.0)) return std::numeric_limits<double>::infinity();
  return s(0) / smallest;
}

std::optional<double> infinityConditionNumber(const Eigen::MatrixXd& K) {
  if (K.rows() > kMaxConditionSize || K.cols() > kMaxConditionSize) return std::nullopt;
  if (K.size() == 0) return 1.0;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
  if (!lu.isInvertible()) return std::numeric_limits<double>::infinity();
  const auto rowSumNorm = [](const Eigen::MatrixXd& M) { return M.cwiseAbs().rowwise().sum().maxCoeff(); };
  return rowSumNorm(K) * rowSumNorm(lu.inverse());
}

}  // namespace rt
