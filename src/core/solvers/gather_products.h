// The products of F with B that the gathering solvers spend their time in, laid out per platform. A dense F
// of 5,000 elements is 200 MB: a pass over it is the unit of a solve's cost, so a Gauss-Seidel sweep reads
// each row once and also gives F times the B it started from (the previous iterate's residual), instead of a
// second pass for the residual. Natively Eigen's vectorised row products are the fastest; in WebAssembly
// Eigen has no SIMD path, and its products run about twice as slow as a plain loop, so that build takes a
// loop of its own over WebAssembly's two-lane SIMD. Both sum the same terms; only the rounding of the sums
// differs.
#pragma once

#include "core/formfactor/formfactor_matrix.h"
#include "core/vec.h"

namespace rt::solver_detail {

// F B (n x 3), row by row; with `rowSums`, also each row's sum from the same reading of the row.
RgbField productWithF(const FormFactorMatrix& F, const RgbField& B, Eigen::VectorXd* rowSums = nullptr);

// B during a Gauss-Seidel sweep: this sweep's values of the rows already updated, the last sweep's of the
// rest, and (when the product is asked for) the last sweep's of every row.
class SweepState {
 public:
  explicit SweepState(const RgbField& B);
  // The values now held become the last sweep's.
  void startSweep();
  // Row i of F times B as the sweep holds it; with `last`, also row i of F times the last sweep's B, from the
  // same reading of the row.
  Eigen::RowVector3d gather(const FormFactorMatrix& F, Eigen::Index i, Eigen::RowVector3d* last) const;
  Eigen::RowVector3d row(Eigen::Index i) const;
  void setRow(Eigen::Index i, const Eigen::RowVector3d& value);
  // B as held (this sweep's values where updated).
  RgbField current() const;

 private:
#ifdef __EMSCRIPTEN__
  // This sweep's values and the last's, one array per channel (as RgbField keeps them): two entries of a row
  // of F meet two elements' values of a channel in one SIMD product.
  RgbField now_, last_;
#else
  // Columns 0-2 this sweep's values, 3-5 the last sweep's: one product of a row with six columns.
  Eigen::Matrix<double, Eigen::Dynamic, 6> values_;
#endif
};

}  // namespace rt::solver_detail
