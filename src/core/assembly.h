// The matrix of the radiosity system, K = I - diag(rho) F, one RGB channel at a time, and the numbers that
// say how hard it is to solve: the spectral radius of rho F (iterative methods converge like its powers) and
// the condition number of K (how much the direct solution amplifies errors in E and F).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <optional>

#include "core/formfactor/formfactor_matrix.h"
#include "core/solvers/radiosity_system.h"

namespace rt {

using SparseRowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Fraction of the entries of F that are non-zero.
double fillFraction(const FormFactorMatrix& F);
// K = I - diag(rho) F.
Eigen::MatrixXd assembleDense(const FormFactorMatrix& F, const Eigen::VectorXd& rho);
SparseRowMatrix assembleSparse(const FormFactorMatrix& F, const Eigen::VectorXd& rho);

// Below this fill (scenes where most elements cannot see each other) K is stored sparse.
constexpr double kSparseFillThreshold = 0.1;

struct AssembledMatrix {
  int channel = 0;
  double fill = 1.0;    // of F
  bool sparse = false;  // which of the two is filled
  Eigen::MatrixXd dense;
  SparseRowMatrix sparseK;
  Eigen::MatrixXd toDense() const;
};

// channel: 0 = red, 1 = green, 2 = blue. Sparse when fillFraction(F) < sparseBelowFill.
AssembledMatrix assemble(const RadiositySystem& system, int channel,
                         double sparseBelowFill = kSparseFillThreshold);

struct SpectralRadiusEstimate {
  double value = 0;             // best estimate (mid-point of the bounds)
  double lower = 0, upper = 0;  // Collatz-Wielandt bounds: the true value lies in between
  int iterations = 0;
  bool converged = false;
};

// Spectral radius of M = diag(rho) F (non-negative) by power iteration on M + I, which has the same Perron
// vector but no other eigenvalue of the same modulus (plain power iteration oscillates for two facing plates,
// F = [0 1; 1 0]).
SpectralRadiusEstimate spectralRadius(const FormFactorMatrix& F, const Eigen::VectorXd& rho,
                                      int maxIterations = 20000, double tolerance = 1e-10);

// Largest n for which conditionNumber() runs an O(n^3) SVD.
constexpr Eigen::Index kMaxConditionSize = 1500;
// 2-norm condition number sigma_max / sigma_min by SVD; nullopt when n > kMaxConditionSize. Infinity when
// singular.
std::optional<double> conditionNumber(const Eigen::MatrixXd& K);
// Infinity-norm condition number ||K|| ||K^-1|| (largest absolute row sum), by an LU inverse; nullopt when
// n > kMaxConditionSize, infinity when singular. It is the norm in which the book bounds it by ρ alone:
// (1 + m) / (1 - m) with m = max_i ρ_i Σ_j F_ij, met exactly by a closed room of one reflectance.
std::optional<double> infinityConditionNumber(const Eigen::MatrixXd& K);

}  // namespace rt
