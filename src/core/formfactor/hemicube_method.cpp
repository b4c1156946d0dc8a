// "hemicube": one hemicube per element at its centroid (options.hemicubeResolution), every other element
// z-buffered onto it. Visibility comes for free from the z-buffer; the price is aliasing and the
// point-at-centroid assumption, which is poor for adjacent elements. Rows are independent, so no reciprocity
// is used.
#include <algorithm>
#include <vector>

#include "core/formfactor/analytic_method.h"
#include "core/formfactor/hemicube.h"
#include "core/formfactor/pair_matrix.h"

namespace rt {
namespace {

class HemicubeMethod : public FormFactorMethod {
 public:
  std::string name() const override { return "hemicube"; }
  AccuracyKnob knob() const override {
    return {AccuracyKnob::Field::Resolution,
            "resolution",
            "pixels along the edge of the hemicube's top face",
            2,
            4096,
            128};
  }
  std::string description() const override {
    return "z-buffered hemicube at each element's centroid (Cohen & Greenberg 1985)";
  }
  bool rowsAreIndependent() const override { return true; }
  bool readsOnlyItsKnob() const override { return true; }
  FormFactorMatrix computeMatrix(const Mesh& mesh, const FormFactorOptions& options, Progress& progress,
                                 FormFactorStats& stats) const override {
    const int resolution = std::max(2, options.hemicubeResolution);
    for (int f = 0; f < 5; ++f) deltaFormFactors(resolution, static_cast<HemicubeFace>(f));  // warm the cache
    const auto n = static_cast<Eigen::Index>(mesh.size());
    FormFactorMatrix F = zeroFormFactorMatrix(n);
    const HemicubeMesh elements(mesh);
    forEachRow(mesh.size(), options, progress, "form factors (hemicube)", stats, [&](int i, RowCounters&) {
      // One workspace per worker thread: the face buffers are reused row after row instead of being
      // allocated and freed (large blocks, mapped and unmapped by the allocator every time).
      thread_local HemicubeWorkspace workspace;
      // Accumulate in a cache-resident row, then write the matrix row once: the matrix's fresh pages are
      // first touched by a write, not by the read of "+=" (which maps the shared zero page and then pays a
      // copy-on-write fault with a TLB flush on every core).
      thread_local std::vector<double> row;
      row.resize(static_cast<std::size_t>(n));
      hemicubeRow(elements, i, resolution, workspace, row.data());
      std::copy(row.begin(), row.end(), F.row(i).data());
    });
    return F;
  }

 protected:
  void checkRows(const Mesh&, const FormFactorOptions& options, const FormFactorMatrix&, const RowSums& rows,
                 FormFactorStats& stats) const override {
    const int resolution = std::max(2, options.hemicubeResolution);
    stats.pairsComputed = rows.positive;
    stats.notes =
        "hemicube " + std::to_string(resolution) + "x" + std::to_string(resolution) + " at centroids";
    // A row distributes the hemicube's pixels: it cannot exceed their delta form factors' total (~1).
    double pixels = 0;
    for (int f = 0; f < 5; ++f)
      for (double d : deltaFormFactors(resolution, static_cast<HemicubeFace>(f))) pixels += d;
    checkRowSumsAtMost(rows, pixels, "hemicube");
  }
};

}  // namespace

std::unique_ptr<FormFactorMethod> makeHemicubeMethod() {
  return std::make_unique<HemicubeMethod>();
}

}  // namespace rt
