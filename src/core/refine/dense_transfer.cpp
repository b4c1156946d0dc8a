#include "core/refine/dense_transfer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>

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
  FormFactorMatrix F = FormFactorMatrix::Zero(n, n);
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
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(start, end), [&](const tbb::blocked_range<std::size_t>& r) {
          std::size_t local = 0;
          for (std::size_t k = r.begin(); k != r.end(); ++k) {
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

int gatherSolve(const FormFactorMatrix& F, const RgbField& reflectance, const RgbField& emission, RgbField& B,
                double tolerance, int maxSweeps, Progress& progress) {
  const Eigen::Index n = F.rows();
  if (B.rows() != n) B = emission;
  for (int sweep = 1; sweep <= maxSweeps; ++sweep) {
    if (progress.cancelled()) throw Cancelled();
    double change = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::RowVector3d gathered = F.row(i) * B;
      const Eigen::RowVector3d next =
          emission.row(i) + (reflectance.row(i).array() * gathered.array()).matrix();
      change = std::max(change, (next - B.row(i)).cwiseAbs().maxCoeff());
      B.row(i) = next;
    }
    if (change <= tolerance * std::max(B.cwiseAbs().maxCoeff(), 1e-300)) return sweep;
  }
  return maxSweeps;
}

}  // namespace rt
