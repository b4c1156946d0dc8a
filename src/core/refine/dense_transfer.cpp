#include "core/refine/dense_transfer.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>

#include "core/parallel.h"
#include "core/solvers/gathering_solvers.h"

namespace rt {

std::vector<SurfacePiece> piecesOfMesh(const Mesh& mesh, std::vector<Polygon>& polygons) {
  polygons.clear();
  polygons.reserve(mesh.size());
  for (std::size_t e = 0; e < mesh.size(); ++e) polygons.push_back(mesh.polygon(static_cast<int>(e)));
  std::vector<SurfacePiece> pieces;
  pieces.reserve(mesh.size());
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& el = mesh.elements[e];
    pieces.push_back({&polygons[e], el.normal, el.centroid, el.area, el.patch});
  }
  return pieces;
}

FormFactorMatrix updateFormFactors(const FormFactorMatrix& previous, const std::vector<int>& oldIndex,
                                   const std::vector<SurfacePiece>& pieces,
                                   const VisibilityOracle& visibility, const TransferOptions& options,
                                   Progress& progress, const std::string& stage, std::size_t& pairsComputed) {
  const int n = static_cast<int>(pieces.size());
  auto isNew = [&](int a) { return oldIndex.empty() || oldIndex[a] < 0; };
  FormFactorMatrix F = zeroFormFactorMatrix(n);
  std::vector<int> fresh;
  for (int a = 0; a < n; ++a) {
    if (isNew(a)) {
      fresh.push_back(a);
      continue;
    }
    for (int b = 0; b < n; ++b)
      if (!isNew(b)) F(a, b) = previous(oldIndex[a], oldIndex[b]);
  }
  // Each unordered pair with at least one new element is evaluated once, by the thread owning its new element
  // of lower index; the pair's two entries are written by that thread only.
  std::atomic<std::size_t> pairs{0};
  const int block = 32;
  for (std::size_t start = 0; start < fresh.size(); start += block) {
    if (progress.cancelled()) throw Cancelled();
    progress.report(static_cast<double>(start) / static_cast<double>(std::max<std::size_t>(1, fresh.size())),
                    stage);
    const std::size_t end = std::min(fresh.size(), start + block);
    parallelForChunks(start, end, {}, [&](std::size_t lo, std::size_t hi) {
      std::size_t local = 0;
      for (std::size_t k = lo; k != hi; ++k) {
        const int a = fresh[k];
        for (int b = 0; b < n; ++b) {
          if (b == a || (isNew(b) && b < a)) continue;
          const auto [fab, fba] = pieceFormFactors(pieces[a], pieces[b], visibility, options);
          F(a, b) = fab;
          F(b, a) = fba;
          ++local;
        }
      }
      pairs += local;
    });
  }
  progress.report(1.0, stage);
  pairsComputed = pairs.load();
  return F;
}

int gatherSolve(const RadiositySystem& system, RgbField& B, double tolerance, int maxSweeps,
                Progress& progress) {
  SolverOptions options;
  options.tolerance = tolerance;
  options.maxIterations = maxSweeps;
  options.recordHistory = false;
  int sweeps = 0;
  const SolverStatus status = gaussSeidel(system, B, options, [&](const IterationRecord& record) {
    sweeps = record.iteration;
    if (progress.cancelled()) throw Cancelled();
  });
  // The meshes come from validated scenes (rho < 1), so anything but convergence or the sweep cap is a bug.
  if (status != SolverStatus::Success && status != SolverStatus::NoConvergence)
    throw std::logic_error("refinement solve failed: " + toString(status));
  return sweeps;
}

}  // namespace rt
