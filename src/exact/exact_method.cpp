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
    return exactFormFactors(mesh, exactOptionsFor(options.tolerance), progress, &stats, options.threads,
                            options.workBudget)
        .F;
  }
};

// Pairs i < j that face each other with candidate occluders in their shaft: the entries that need
// cubature.
std::size_t countOccludedPairs(const Mesh& mesh, const ElementIndex& index, int threads) {
  const auto n = static_cast<int>(mesh.size());
  std::atomic<std::size_t> count{0};
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, n, 1), [&](const tbb::blocked_range<int>& r) {
      for (int i = r.begin(); i != r.end(); ++i)
        for (int j = i + 1; j < n; ++j) {
          const PairGeometry pair = setUpPair(mesh, i, j, true, &index);
          if (pair.facing && !pair.occluders.empty()) ++count;
        }
    });
  });
  return count.load();
}

}  // namespace

ExactMatrix exactFormFactors(const Mesh& mesh, const ExactOptions& entryOptions, Progress& progress,
                             FormFactorStats* stats, int threads, long workBudget) {
  const auto start = std::chrono::steady_clock::now();
  const auto n = static_cast<Eigen::Index>(mesh.size());
  ExactMatrix result{zeroFormFactorMatrix(n), Eigen::MatrixXd::Zero(n, n)};
  std::atomic<std::size_t> computed{0}, facing{0}, unoccluded{0}, pairsDone{0};
  const std::size_t totalPairs =
      static_cast<std::size_t>(n) * static_cast<std::size_t>(std::max<Eigen::Index>(n - 1, 0)) / 2;
  std::atomic<long> evaluations{0}, exactEvaluations{0}, splitEvaluations{0}, notConverged{0};
  // Point evaluations so far, entries in progress included (an analytic entry counts 1), and those of the
  // finished occluded entries.
  std::atomic<long> work{0}, occludedWork{0};
  std::atomic<std::size_t> occludedDone{0};
  std::mutex progressMutex;  // reporters need not be thread-safe
  double reported = 0;
  const std::string stage = "exact form factors";
  progress.report(0.0, stage);
  const ElementIndex index(mesh);
  const std::size_t occludedPairs = countOccludedPairs(mesh, index, threads);

  // The fraction of the work done. An occluded entry takes from a few hundred point evaluations to the cap,
  // an unoccluded one a single contour integral, and the occluded ones are counted before the run (their
  // shafts, a small part of the whole): the whole is estimated as the work done plus the occluded entries
  // not yet finished at the mean cost of the finished ones (kMeterBatch each before any has finished). The
  // bar never goes back; a budget, when given, bounds the whole.
  auto report = [&](bool checkCancel) {
    std::lock_guard lock(progressMutex);
    const double done = static_cast<double>(work.load());
    const double finished = static_cast<double>(occludedDone.load());
    const double mean = finished > 0 ? static_cast<double>(occludedWork.load()) / finished : kMeterBatch;
    double whole = done + std::max(0.0, static_cast<double>(occludedPairs) - finished) * mean +
                   static_cast<double>(totalPairs - std::min(totalPairs, pairsDone.load()));
    if (workBudget > 0) whole = std::min(whole, static_cast<double>(workBudget));
    if (whole > 0) reported = std::max(reported, std::min(0.999, done / whole));
    progress.report(reported, stage);
    if (checkCancel && progress.cancelled()) throw Cancelled();
  };
  auto spend = [&](long evaluationsSpent) {
    const long total = work += evaluationsSpent;
    if (workBudget > 0 && total > workBudget)
      throw WorkBudgetExceeded(
          "exact form factors stopped: the work budget of " + std::to_string(workBudget) +
          " point evaluations (--ff-budget) ran out after " + std::to_string(pairsDone.load()) + " of " +
          std::to_string(totalPairs) +
          " element pairs; raise the budget, loosen --ff-tolerance or use fewer elements");
  };
  ExactOptions options = entryOptions;
  options.meter = [&](long batch) {
    spend(batch);
    report(true);
  };

  auto row = [&](Eigen::Index i) {
    if (progress.cancelled()) throw Cancelled();
    const double ai = mesh.elements[i].area;
    for (Eigen::Index j = i + 1; j < n; ++j) {
      const EntryResult e =
          elementFormFactor(mesh, static_cast<int>(i), static_cast<int>(j), options, nullptr, &index);
      ++pairsDone;
      if (!e.facing) {
        ++facing;
        continue;
      }
      if (e.evaluations == 0) spend(1);  // the analytic value, or wholly hidden: one step of work
      ++computed;
      if (!e.occluded) ++unoccluded;
      if (e.occluded) {
        occludedWork += e.evaluations;
        ++occludedDone;
      }
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
    report(true);
  };

  // A throw in any row (Cancelled, WorkBudgetExceeded) cancels the others and comes out of execute().
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, n, 1),
                      [&](const tbb::blocked_range<Eigen::Index>& r) {
                        for (Eigen::Index i = r.begin(); i != r.end(); ++i) row(i);
                      });
  });

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
