// The form-factor matrix and the diagnostics every method reports.
// Convention (docs/conventions.md): F(i,j) = (1/A_i) int_Ai int_Aj cos_i cos_j V / (pi r^2) dA_j dA_i, the
// fraction of power leaving element i that arrives at element j. Rows sum to <= 1 (= 1 in a closed scene);
// A_i F_ij = A_j F_ji.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace rt {

// Dense, row-major: a row is what one element sees, which is what shooting and gathering walk along.
using FormFactorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A zeroed n x n matrix. Throws InputError, before allocating, when it cannot fit in memory: the message
// gives n, the bytes needed and the machine's memory (a dense F grows as n^2: 100,000 elements need 75 GB).
FormFactorMatrix zeroFormFactorMatrix(Eigen::Index n);

// What the checks after a method read of every row, from one pass over F: a dense F of 5,000 elements is
// 200 MB, so each pass costs as much as a sweep of the solve.
struct RowSums {
  Eigen::VectorXd sums;      // each row's sum
  std::size_t positive = 0;  // entries > 0 (the pairs that see each other)
};
RowSums sumRows(const FormFactorMatrix& F);
// The sum of n entries in four interleaved partial sums: one chain of additions waits on each addition, four
// chains run side by side. NaN or infinite exactly when an entry is, or when finite entries overflow.
double sumOf(const double* entries, Eigen::Index n);

// RT_CHECK that no row of F sums to more than `bound` (+ rounding): the contract of the methods whose rows
// are fractions of one set of samples (a hemicube's delta form factors, Monte Carlo's rays). A no-op in
// builds without checks.
void checkRowSumsAtMost(const RowSums& rows, double bound, const std::string& method);

struct FormFactorDiagnostics {
  // Over the rows of elements that see something. An element that sees nothing (a block's bottom on the
  // floor, a floor element under a block that sees only the block's back faces) has a row of zeros, which is
  // right and says nothing about closure: those are counted and listed apart.
  double minRowSum = 0, maxRowSum = 0;
  double maxClosureError = 0;       // max |1 - sum_j F_ij| (meaningful in a closed scene)
  long blindRows = 0;               // rows that sum to (almost) 0: the element sees nothing
  std::vector<long> blindExamples;  // the first few of them
  double maxReciprocityError = 0;   // max |A_i F_ij - A_j F_ji| / max(A_i F_ij, A_j F_ji) over non-zero pairs
  long negativeEntries = 0;
  long entriesAboveOne = 0;
  std::string summary() const;  // one line
};

FormFactorDiagnostics diagnose(const FormFactorMatrix& F, const Eigen::VectorXd& areas);

// Opt-in repairs (never on by default: silently fixing form factors hides errors).
// Replaces both F_ij and F_ji by the area-weighted average that satisfies reciprocity exactly.
void enforceReciprocity(FormFactorMatrix& F, const Eigen::VectorXd& areas);
// Scales every non-zero row to sum to 1 (only right for closed scenes).
void normalizeRows(FormFactorMatrix& F);

}  // namespace rt
