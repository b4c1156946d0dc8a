#include "core/formfactor/formfactor_matrix.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/check.h"
#include "core/input_error.h"
#include "core/memory_budget.h"

namespace rt {

FormFactorMatrix zeroFormFactorMatrix(Eigen::Index n) {
  const double bytes = 8.0 * static_cast<double>(n) * static_cast<double>(n), budget = memoryBudgetBytes();
  if (bytes > budget)
    throw InputError({}, "the form-factor matrix of " + formatCount(static_cast<double>(n)) +
                             " elements needs " + formatBytes(bytes) + " (n^2 doubles); this machine has " +
                             formatBytes(budget) +
                             ". Use a coarser mesh (a larger --max-edge), --mesh hierarchical, or a shooting "
                             "solver with --no-matrix");
  return FormFactorMatrix::Zero(n, n);
}

RowSums sumRows(const FormFactorMatrix& F) {
  RowSums out;
  out.sums.resize(F.rows());
  for (Eigen::Index i = 0; i < F.rows(); ++i) {
    const double* row = F.row(i).data();
    out.sums[i] = sumOf(row, F.cols());
    std::size_t positive = 0;
    for (Eigen::Index j = 0; j < F.cols(); ++j) positive += row[j] > 0 ? 1 : 0;
    out.positive += positive;
  }
  return out;
}

double sumOf(const double* entries, Eigen::Index n) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  Eigen::Index j = 0;
  for (; j + 4 <= n; j += 4)
    s0 += entries[j], s1 += entries[j + 1], s2 += entries[j + 2], s3 += entries[j + 3];
  for (; j < n; ++j) s0 += entries[j];
  return (s0 + s1) + (s2 + s3);
}

void checkRowSumsAtMost(const RowSums& rows, double bound, const std::string& method) {
  if (!checksEnabled()) return;
  // A sum of n correctly rounded terms may gather up to n half-ulps: the bound allows for that arithmetic,
  // and only for it.
  const double rounding = static_cast<double>(rows.sums.size()) * std::numeric_limits<double>::epsilon();
  for (Eigen::Index i = 0; i < rows.sums.size(); ++i) {
    const double sum = rows.sums[i];
    RT_CHECK(sum <= bound * (1 + 1e-12 + rounding) + 1e-12, method + ": row " + std::to_string(i) +
                                                                " of F sums to " + std::to_string(sum) +
                                                                ", more than " + std::to_string(bound));
  }
}

std::string FormFactorDiagnostics::summary() const {
  char line[256];
  std::snprintf(
      line, sizeof line,
      "row sums [%.6g, %.6g], max |1 - row sum| %.3g, reciprocity error %.3g, %ld negative, %ld > 1",
      minRowSum, maxRowSum, maxClosureError, maxReciprocityError, negativeEntries, entriesAboveOne);
  std::string out = line;
  if (blindRows == 0) return out;
  out += "; " + std::to_string(blindRows) + (blindRows == 1 ? " element sees" : " elements see") +
         " nothing (hidden or enclosed, e.g. ";
  for (std::size_t k = 0; k < blindExamples.size(); ++k)
    out += (k ? ", " : "") + std::to_string(blindExamples[k]);
  return out + (static_cast<long>(blindExamples.size()) < blindRows ? ", ...)" : ")") +
         ": the row sums above are over the others";
}

FormFactorDiagnostics diagnose(const FormFactorMatrix& F, const Eigen::VectorXd& areas) {
  FormFactorDiagnostics d;
  const Eigen::Index n = F.rows();
  if (n == 0) return d;
  const Eigen::VectorXd sums = F.rowwise().sum();
  constexpr double kBlind = 1e-9;  // far below any row of an element that sees a surface at all
  constexpr std::size_t kExamples = 5;
  d.minRowSum = d.maxRowSum = 0;
  bool first = true;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (std::abs(sums[i]) < kBlind) {
      if (d.blindExamples.size() < kExamples) d.blindExamples.push_back(static_cast<long>(i));
      ++d.blindRows;
      continue;
    }
    d.minRowSum = first ? sums[i] : std::min(d.minRowSum, sums[i]);
    d.maxRowSum = first ? sums[i] : std::max(d.maxRowSum, sums[i]);
    d.maxClosureError = std::max(d.maxClosureError, std::abs(1.0 - sums[i]));
    first = false;
  }
  d.negativeEntries = (F.array() < 0.0).count();
  d.entriesAboveOne = (F.array() > 1.0).count();
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i + 1; j < n; ++j) {
      const double a = areas[i] * F(i, j), b = areas[j] * F(j, i);
      const double scale = std::max(std::abs(a), std::abs(b));
      if (scale > 0) d.maxReciprocityError = std::max(d.maxReciprocityError, std::abs(a - b) / scale);
    }
  return d;
}

void enforceReciprocity(FormFactorMatrix& F, const Eigen::VectorXd& areas) {
  const Eigen::Index n = F.rows();
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i + 1; j < n; ++j) {
      const double exchange = 0.5 * (areas[i] * F(i, j) + areas[j] * F(j, i));
      F(i, j) = exchange / areas[i];
      F(j, i) = exchange / areas[j];
    }
}

void normalizeRows(FormFactorMatrix& F) {
  for (Eigen::Index i = 0; i < F.rows(); ++i) {
    const double s = F.row(i).sum();
    if (s > 0) F.row(i) /= s;
  }
}

}  // namespace rt
