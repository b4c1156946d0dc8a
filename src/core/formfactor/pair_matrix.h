// Shared machinery of the form-factor methods: parallel rows with progress and cancellation, the facing test,
// and the symmetric driver that integrates each pair once and derives the other direction by reciprocity.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "core/formfactor/formfactor_method.h"
#include "core/mesh.h"

namespace rt {

// False when one element lies entirely on or behind the other's plane: then F_ij = F_ji = 0 without
// integration.
bool elementsFaceEachOther(const Mesh& mesh, int i, int j);

// Counters a row accumulates locally and the driver adds into FormFactorStats.
struct RowCounters {
  std::size_t pairsComputed = 0, pairsSkippedFacing = 0, pairsByReciprocity = 0, pairsUnoccluded = 0,
              raysCast = 0, kernelEvaluations = 0, contourIntegrals = 0;
  double varianceSum = 0;  // stochastic methods: sum over entries of the estimator variance
};

// The counts RowCounters and FormFactorStats share (all but the variance), as pairs of fields: the one list
// of them, so that adding a counter to both cannot be forgotten in one of the merges.
template <class To, class From>
void addCounts(To& to, const From& from) {
  to.pairsComputed += from.pairsComputed;
  to.pairsSkippedFacing += from.pairsSkippedFacing;
  to.pairsByReciprocity += from.pairsByReciprocity;
  to.pairsUnoccluded += from.pairsUnoccluded;
  to.raysCast += from.raysCast;
  to.kernelEvaluations += from.kernelEvaluations;
  to.contourIntegrals += from.contourIntegrals;
}

// Runs rowFunction(i, counters) for every row in parallel (TBB, options.threads), reports progress per chunk
// of rows under `stage`, and throws Cancelled when progress.cancelled() (checked before each row).
void forEachRow(std::size_t rows, const FormFactorOptions& options, Progress& progress,
                const std::string& stage, FormFactorStats& stats,
                const std::function<void(int row, RowCounters& counters)>& rowFunction);

// The result of integrating one pair.
struct PairResult {
  double value = 0;                   // F_ij
  std::size_t rays = 0;               // rays cast for it
  bool needsVisibility = false;       // false: the shaft test proved it unoccluded
  std::size_t kernelEvaluations = 0;  // point-to-polygon (Lambert) evaluations, for methods that count them
  std::size_t contourIntegrals = 0;   // exact polygon-to-polygon contour integrals, likewise
};

// F_ij for a method that estimates on the element it samples: integrate(a, b) runs from the smaller of i and
// j and the result is scaled to i -> j by reciprocity. An estimate made on the larger element would be
// multiplied by A_large / A_small on the way back (1000 for a 1000:1 sliver against its neighbour), and so
// would its error. Equal areas (to rounding, which changes with the units) keep the pair's order.
template <class Integrate>
PairResult fromSmallerElement(const Mesh& mesh, int i, int j, Integrate&& integrate) {
  const double ai = mesh.elements[i].area, aj = mesh.elements[j].area;
  if (ai <= aj * (1 + 1e-9)) return integrate(i, j);
  PairResult result = integrate(j, i);
  result.value *= aj / ai;
  return result;
}

// For methods whose pair integral is symmetric (analytic, raycast): computes F_ij for i < j only when the
// elements face each other, sets F_ji = A_i F_ij / A_j. With `useSkipRules` false every ordered pair is
// integrated (for tests that check the rules never change the answer).
FormFactorMatrix computeReciprocalMatrix(const Mesh& mesh, const FormFactorOptions& options,
                                         Progress& progress, FormFactorStats& stats, const std::string& stage,
                                         const std::function<PairResult(int i, int j)>& pairFunction,
                                         bool useSkipRules = true);

}  // namespace rt
