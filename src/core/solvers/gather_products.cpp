#include "core/solvers/gather_products.h"

namespace rt::solver_detail {

#ifdef __EMSCRIPTEN__

namespace {

// sum_j f[j] b[3j + c] for j in [begin, end), c = 0, 1, 2.
inline void addRowTimes(const double* f, const double* b, Eigen::Index begin, Eigen::Index end, double& s0,
                        double& s1, double& s2) {
  for (Eigen::Index j = begin; j < end; ++j) {
    const double v = f[j];
    s0 += v * b[3 * j];
    s1 += v * b[3 * j + 1];
    s2 += v * b[3 * j + 2];
  }
}

}  // namespace

RgbField productWithF(const FormFactorMatrix& F, const RgbField& B) {
  const Eigen::Matrix<double, 3, Eigen::Dynamic> b = B.transpose();
  RgbField out(F.rows(), 3);
  for (Eigen::Index i = 0; i < F.rows(); ++i) {
    double s0 = 0, s1 = 0, s2 = 0;
    addRowTimes(F.row(i).data(), b.data(), 0, F.cols(), s0, s1, s2);
    out.row(i) << s0, s1, s2;
  }
  return out;
}

SweepState::SweepState(const RgbField& B) : now_(B.transpose()), last_(now_) {}

void SweepState::startSweep() {
  last_ = now_;
}

Eigen::RowVector3d SweepState::gather(const FormFactorMatrix& F, Eigen::Index i,
                                      Eigen::RowVector3d* last) const {
  const double* f = F.row(i).data();
  double u0 = 0, u1 = 0, u2 = 0;  // the rows from i on hold the last sweep's values in both
  addRowTimes(f, last_.data(), i, F.cols(), u0, u1, u2);
  double n0 = 0, n1 = 0, n2 = 0;
  if (!last) {
    addRowTimes(f, now_.data(), 0, i, n0, n1, n2);
    return {n0 + u0, n1 + u1, n2 + u2};
  }
  double l0 = 0, l1 = 0, l2 = 0;
  const double *now = now_.data(), *before = last_.data();
  for (Eigen::Index j = 0; j < i; ++j) {
    const double v = f[j];
    n0 += v * now[3 * j];
    n1 += v * now[3 * j + 1];
    n2 += v * now[3 * j + 2];
    l0 += v * before[3 * j];
    l1 += v * before[3 * j + 1];
    l2 += v * before[3 * j + 2];
  }
  *last = {l0 + u0, l1 + u1, l2 + u2};
  return {n0 + u0, n1 + u1, n2 + u2};
}

Eigen::RowVector3d SweepState::row(Eigen::Index i) const {
  return now_.col(i).transpose();
}

void SweepState::setRow(Eigen::Index i, const Eigen::RowVector3d& value) {
  now_.col(i) = value.transpose();
}

RgbField SweepState::current() const {
  return now_.transpose();
}

#else

RgbField productWithF(const FormFactorMatrix& F, const RgbField& B) {
  // Row by row: Eigen's product of the whole matrix with three columns takes twice as long.
  RgbField out(F.rows(), 3);
  for (Eigen::Index i = 0; i < F.rows(); ++i) out.row(i).noalias() = F.row(i) * B;
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
