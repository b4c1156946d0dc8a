#include "core/solvers/gather_products.h"

#ifdef __EMSCRIPTEN__
#include <wasm_simd128.h>
#endif

namespace rt::solver_detail {

#ifdef __EMSCRIPTEN__

namespace {

// Two lanes of f64x2: WebAssembly's SIMD (this file is built with -msimd128), two entries of F per step.
struct Sums {
  v128_t lanes = wasm_f64x2_splat(0.0);
  void add(v128_t f, const double* channel) {
    lanes = wasm_f64x2_add(lanes, wasm_f64x2_mul(f, wasm_v128_load(channel)));
  }
  double total() const { return wasm_f64x2_extract_lane(lanes, 0) + wasm_f64x2_extract_lane(lanes, 1); }
};

// sum_j f[j] B(j, c) for j in [begin, end), c = 0, 1, 2; B column-major (one array per channel).
inline Eigen::RowVector3d rowTimes(const double* f, const RgbField& B, Eigen::Index begin, Eigen::Index end) {
  const double *b0 = B.col(0).data(), *b1 = B.col(1).data(), *b2 = B.col(2).data();
  Sums s0, s1, s2;
  Eigen::Index j = begin;
  for (; j + 2 <= end; j += 2) {
    const v128_t v = wasm_v128_load(f + j);
    s0.add(v, b0 + j);
    s1.add(v, b1 + j);
    s2.add(v, b2 + j);
  }
  Eigen::RowVector3d sum(s0.total(), s1.total(), s2.total());
  if (j < end) sum += f[j] * Eigen::RowVector3d(b0[j], b1[j], b2[j]);
  return sum;
}

}  // namespace

RgbField productWithF(const FormFactorMatrix& F, const RgbField& B, Eigen::VectorXd* rowSums) {
  RgbField out(F.rows(), 3);
  if (rowSums) rowSums->resize(F.rows());
  for (Eigen::Index i = 0; i < F.rows(); ++i) {
    out.row(i) = rowTimes(F.row(i).data(), B, 0, F.cols());
    if (rowSums) (*rowSums)[i] = sumOf(F.row(i).data(), F.cols());  // the row is in the cache now
  }
  return out;
}

SweepState::SweepState(const RgbField& B) : now_(B), last_(B) {}

void SweepState::startSweep() {
  last_ = now_;
}

Eigen::RowVector3d SweepState::gather(const FormFactorMatrix& F, Eigen::Index i,
                                      Eigen::RowVector3d* last) const {
  const double* f = F.row(i).data();
  // The rows from i on hold the last sweep's values in both.
  const Eigen::RowVector3d upper = rowTimes(f, last_, i, F.cols());
  if (!last) return rowTimes(f, now_, 0, i) + upper;
  const double *n0 = now_.col(0).data(), *n1 = now_.col(1).data(), *n2 = now_.col(2).data();
  const double *l0 = last_.col(0).data(), *l1 = last_.col(1).data(), *l2 = last_.col(2).data();
  Sums s0, s1, s2, t0, t1, t2;
  Eigen::Index j = 0;
  for (; j + 2 <= i; j += 2) {
    const v128_t v = wasm_v128_load(f + j);
    s0.add(v, n0 + j);
    s1.add(v, n1 + j);
    s2.add(v, n2 + j);
    t0.add(v, l0 + j);
    t1.add(v, l1 + j);
    t2.add(v, l2 + j);
  }
  Eigen::RowVector3d lowerNow(s0.total(), s1.total(), s2.total()),
      lowerLast(t0.total(), t1.total(), t2.total());
  if (j < i) {
    lowerNow += f[j] * now_.row(j);
    lowerLast += f[j] * last_.row(j);
  }
  *last = lowerLast + upper;
  return lowerNow + upper;
}

Eigen::RowVector3d SweepState::row(Eigen::Index i) const {
  return now_.row(i);
}

void SweepState::setRow(Eigen::Index i, const Eigen::RowVector3d& value) {
  now_.row(i) = value;
}

RgbField SweepState::current() const {
  return now_;
}

#else

RgbField productWithF(const FormFactorMatrix& F, const RgbField& B, Eigen::VectorXd* rowSums) {
  // Row by row: Eigen's product of the whole matrix with three columns takes twice as long.
  RgbField out(F.rows(), 3);
  if (rowSums) rowSums->resize(F.rows());
  for (Eigen::Index i = 0; i < F.rows(); ++i) {
    out.row(i).noalias() = F.row(i) * B;
    if (rowSums) (*rowSums)[i] = sumOf(F.row(i).data(), F.cols());  // the row is in the cache now
  }
  return out;
}

SweepState::SweepState(const RgbField& B) : values_(B.rows(), 6) {
  values_.leftCols<3>() = B;
  values_.rightCols<3>() = B;
}

void SweepState::startSweep() {
  values_.rightCols<3>() = values_.leftCols<3>();
}

Eigen::RowVector3d SweepState::gather(const FormFactorMatrix& F, Eigen::Index i,
                                      Eigen::RowVector3d* last) const {
  const Eigen::Index n = F.cols();
  // The rows from i on hold the last sweep's values in both halves.
  const Eigen::RowVector3d upper = F.row(i).tail(n - i) * values_.bottomRows(n - i).leftCols<3>();
  if (!last) return F.row(i).head(i) * values_.topRows(i).leftCols<3>() + upper;
  const Eigen::Matrix<double, 1, 6> lower = F.row(i).head(i) * values_.topRows(i);
  *last = lower.tail<3>() + upper;
  return lower.head<3>() + upper;
}

Eigen::RowVector3d SweepState::row(Eigen::Index i) const {
  return values_.row(i).head<3>();
}

void SweepState::setRow(Eigen::Index i, const Eigen::RowVector3d& value) {
  values_.row(i).head<3>() = value;
}

RgbField SweepState::current() const {
  return values_.leftCols<3>();
}

#endif

}  // namespace rt::solver_detail
