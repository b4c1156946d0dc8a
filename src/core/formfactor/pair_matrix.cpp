#include "core/formfactor/pair_matrix.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>

#include "core/parallel.h"
#include "core/vector_state.h"

namespace rt {

bool elementsFaceEachOther(const Mesh& mesh, int i, int j) {
  const Element& a = mesh.elements[i];
  const Element& b = mesh.elements[j];
  // Relative tolerance: vertices shared by abutting elements lie exactly on both planes.
  const double eps = 1e-10 * std::sqrt(std::max(a.area, b.area));
  auto anyInFront = [&](const Element& plane, const Element& other) {
    const Vec3& origin = mesh.vertices[plane.vertices[0]];
    for (int v : other.vertices)
      if (plane.normal.dot(mesh.vertices[v] - origin) > eps) return true;
    return false;
  };
  return anyInFront(a, b) && anyInFront(b, a);
}

void forEachRow(std::size_t rows, const FormFactorOptions& options, Progress& progress,
                const std::string& stage, FormFactorStats& stats,
                const std::function<void(int row, RowCounters& counters)>& rowFunction) {
  const auto start = std::chrono::steady_clock::now();
  std::atomic<bool> cancelled{false};
  std::atomic<std::size_t> done{0};
  std::mutex merge;
  RowCounters total;
  const std::size_t reportEvery = std::max<std::size_t>(1, rows / 100);
  progress.report(0.0, stage);
  auto body = [&](std::size_t begin, std::size_t end) {
    // The worker may have been created from a thread whose vector state a library left dirty
    // (vector_state.h).
    clearUpperVectorState();
    RowCounters local;
    for (std::size_t i = begin; i != end; ++i) {
      if (cancelled.load(std::memory_order_relaxed)) return;
      if (progress.cancelled()) {
        cancelled = true;
        return;
      }
      rowFunction(static_cast<int>(i), local);
      const std::size_t finished = done.fetch_add(1) + 1;
      if (finished % reportEvery == 0) {
        std::unique_lock lock(merge, std::try_to_lock);
        if (lock.owns_lock()) progress.report(static_cast<double>(finished) / rows, stage);
      }
    }
    std::lock_guard lock(merge);
    addCounts(total, local);
    total.varianceSum += local.varianceSum;
  };
  // One row per task: rows differ in cost by orders of magnitude (the first rows own the most pairs, and the
  // rows near occluders the most expensive ones), and the automatic partitioner's chunks of many rows left
  // one core idle while the other worked through the expensive chunk. A task per row costs microseconds.
  parallelForChunks(0, rows, {.grain = 1, .chunkPerTask = true, .threads = options.threads}, body);
  if (cancelled) throw Cancelled();
  progress.report(1.0, stage);
  addCounts(stats, total);
  const std::size_t entries = rows * rows;
  if (total.varianceSum > 0 && entries > 0) stats.standardError = std::sqrt(total.varianceSum / entries);
  stats.elements = rows;
  stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

namespace {

// F(j, i) = A_i F(i, j) / A_j for j > i, from the upper triangle, a band of rows j per task.
void mirrorByReciprocity(const Mesh& mesh, const FormFactorOptions& options, FormFactorMatrix& F) {
  constexpr Eigen::Index kTile = 64;
  const Eigen::Index n = F.rows();
  const Eigen::Index bands = (n + kTile - 1) / kTile;
  auto band = [&](Eigen::Index b) {
    clearUpperVectorState();
    const Eigen::Index j0 = b * kTile, j1 = std::min(n, j0 + kTile);
    for (Eigen::Index i0 = 0; i0 < j1; i0 += kTile)
      for (Eigen::Index j = j0; j < j1; ++j) {
        const double aj = mesh.elements[static_cast<std::size_t>(j)].area;
        for (Eigen::Index i = i0; i < std::min(i0 + kTile, j); ++i)
          F(j, i) = F(i, j) * mesh.elements[static_cast<std::size_t>(i)].area / aj;
      }
  };
  parallelFor(Eigen::Index{0}, bands, band, {.threads = options.threads});
}

}  // namespace

FormFactorMatrix computeReciprocalMatrix(const Mesh& mesh, const FormFactorOptions& options,
                                         Progress& progress, FormFactorStats& stats, const std::string& stage,
                                         const std::function<PairResult(int i, int j)>& pairFunction,
                                         bool useSkipRules) {
  const auto n = static_cast<Eigen::Index>(mesh.size());
  FormFactorMatrix F = zeroFormFactorMatrix(n);
  forEachRow(mesh.size(), options, progress, stage, stats, [&](int i, RowCounters& counters) {
    // Row i owns the pairs (i, j > i) and writes both F(i, j) and F(j, i): no two rows touch the same entry.
    const int first = useSkipRules ? i + 1 : 0;
    for (int j = first; j < n; ++j) {
      if (j == i) continue;
      if (useSkipRules && !elementsFaceEachOther(mesh, i, j)) {
        ++counters.pairsSkippedFacing;
        continue;
      }
      const PairResult result = pairFunction(i, j);
      ++counters.pairsComputed;
      counters.raysCast += result.rays;
      counters.kernelEvaluations += result.kernelEvaluations;
      counters.contourIntegrals += result.contourIntegrals;
      if (!result.needsVisibility) ++counters.pairsUnoccluded;
      F(i, j) = result.value;
      if (useSkipRules) ++counters.pairsByReciprocity;
    }
  });
  // F(j, i) = A_i F(i, j) / A_j below the diagonal, in tiles: written along with F(i, j), each entry was a
  // cache and TLB miss (the matrix is row-major; 9,612 elements put the entries of a column 77 kB apart).
  if (useSkipRules) {
    const auto start = std::chrono::steady_clock::now();
    mirrorByReciprocity(mesh, options, F);
    stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return F;
}

}  // namespace rt
