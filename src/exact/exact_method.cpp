// The "exact" form-factor method: every entry by exact visibility and adaptive cubature. Rows run in parallel
// (TBB); only i < j is integrated, F_ji follows from reciprocity A_i F_ij = A_j F_ji.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>

#include "exact/exact_reference.h"
#include "exact/shaft.h"

namespace rt::exact {
namespace {

class ExactMethod : public FormFactorMethod {
 public:
  std::string name() const override { return "exact"; }
  AccuracyKnob knob() const override {
    return {AccuracyKnob::Field::Tolerance,
            "ff-tolerance",
            "requested relative tolerance of each form factor",
            1e-12,
            0.1,
            1e-9};
  }
  double entryErrorBound(double entry, const FormFactorOptions& options) const override {
    return options.tolerance * entry;
  }
  std::string description() const override {
    return "exact reference: visibility by exact 2D Booleans (CGAL), Lambert's formula, adaptive cubature to "
           "--ff-tolerance";
  }
  FormFactorMatrix computeMatrix(const Mesh& mesh, const FormFactorOptions& options, Progress& progress,
                                 FormFactorStats& stats) const override {
    return exactFormFactors(mesh, exactOptionsFor(options.tolerance), progress, &stats, options.threads).F;
  }
};

}  // namespace

ExactMatrix exactFormFactors(const Mesh& mesh, const ExactOptions& options, Progress& progress,
                             FormFactorStats* stats, int threads) {
  const auto start = std::chrono::steady_clock::now();
  const auto n = static_cast<Eigen::Index>(mesh.size());
  ExactMatrix result{zeroFormFactorMatrix(n), Eigen::MatrixXd::Zero(n, n)};
  std::atomic<std::size_t> computed{0}, facing{0}, unoccluded{0}, pairsDone{0};
  const double totalPairs = std::max(1.0, 0.5 * static_cast<double>(n) * static_cast<double>(n - 1));
  std::atomic<long> evaluations{0}, exactEvaluations{0}, splitEvaluations{0}, notConverged{0};
  std::atomic<bool> cancelled{false};
  std::mutex progressMutex;
  const std::string stage = "exact form factors";
  progress.report(0.0, stage);

  const ElementIndex index(mesh);
  auto row = [&](Eigen::Index i) {
    if (cancelled.load() || progress.cancelled()) {
      cancelled = true;
      return;
    }
    const double ai = mesh.elements[i].area;
    for (Eigen::Index j = i + 1; j < n; ++j) {
      const EntryResult e =
          elementFormFactor(mesh, static_cast<int>(i), static_cast<int>(j), options, nullptr, &index);
      if (!e.facing) {
        ++facing;
        continue;
      }
      ++computed;
      if (!e.occluded) ++unoccluded;
      evaluations += e.evaluations;
      exactEvaluations += e.exactEvaluations;
      splitEvaluations += e.splitEvaluations;
      if (!e.converged) ++notConverged;
      const double aj = mesh.elements[j].area;
      result.F(i, j) = e.value;
      result.errorEstimate(i, j) = e.errorEstimate;
      result.F(j, i) = ai * e.value / aj;  // each (i, j) is written by exactly one row task
      result.errorEstimate(j, i) = ai * e.errorEstimate / aj;
    }
    // Rows are uneven (row i integrates n - i - 1 pairs): report the fraction of pairs, not of rows.
    const std::size_t done = pairsDone += static_cast<std::size_t>(n - i - 1);
    std::lock_guard lock(progressMutex);  // reporters need not be thread-safe
    progress.report(static_cast<double>(done) / totalPairs, stage);
    if (progress.cancelled()) cancelled = true;
  };

  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, n, 1),
                      [&](const tbb::blocked_range<Eigen::Index>& r) {
                        for (Eigen::Index i = r.begin(); i != r.end(); ++i) row(i);
                      });
  });
  if (cancelled.load()) throw Cancelled();

  if (stats) {
    stats->elements = mesh.size();
    stats->pairsComputed = computed.load();
    stats->pairsSkippedFacing = 2 * facing.load();
    stats->pairsByReciprocity = computed.load();
    stats->pairsUnoccluded = unoccluded.load();
    stats->raysCast = 0;
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char notes[256];
    std::snprintf(notes, sizeof notes,
                  "%ld point evaluations, penumbra points by %s: %ld, largest error estimate %.2e%s",
                  evaluations.load(),
                  options.booleans == Booleans::Exact ? "exact CGAL Booleans" : "convex split",
                  exactEvaluations.load() + splitEvaluations.load(), result.errorEstimate.maxCoeff(),
                  notConverged.load() ? ", some entries hit the evaluation limit" : "");
    stats->notes = notes;
  }
  progress.report(1.0, stage);
  return result;
}

void registerExactMethod() {
  registerFormFactorMethod("exact", [] { return std::make_unique<ExactMethod>(); });
}

}  // namespace rt::exact
