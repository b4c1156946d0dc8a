#include "core/solvers/row_providers.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/formfactor/hemicube.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/raycast_pair.h"
#include "core/formfactor/visibility.h"

namespace rt {
namespace {

// A caller's mistake, not the input's: the storage of a row has one entry per element.
void checkRowLength(std::span<double> row, std::size_t elements) {
  if (row.size() != elements)
    throw std::invalid_argument("a row of F has one entry per element: " + std::to_string(row.size()) +
                                " given for " + std::to_string(elements));
}

FormFactorRowProvider hemicubeRows(const Mesh& mesh, int resolution) {
  // The workspace is reused from shot to shot: no allocation after the first hemicube.
  auto workspace = std::make_shared<HemicubeWorkspace>();
  auto elements = std::make_shared<const HemicubeMesh>(mesh);
  return [elements, resolution, workspace](int i, std::span<double> row) {
    checkRowLength(row, elements->elements.size());
    hemicubeRow(*elements, i, resolution, *workspace, row.data());
  };
}

FormFactorRowProvider raycastRows(const Mesh& mesh, const FormFactorOptions& options) {
  auto visibility = std::make_shared<const PairVisibility>(mesh);
  const int samples = std::clamp(options.samples, 1, 1024);
  const std::uint64_t seed = options.seed;
  return [&mesh, visibility, samples, seed](int i, std::span<double> row) {
    checkRowLength(row, mesh.size());
    std::fill(row.begin(), row.end(), 0.0);
    const double ai = mesh.elements[i].area;
    auto estimate = [&](int a, int b) { return estimateRaycastPair(mesh, *visibility, a, b, samples, seed); };
    for (int j = 0; j < static_cast<int>(mesh.size()); ++j) {
      if (j == i || !elementsFaceEachOther(mesh, i, j)) continue;
      // As in the matrix method: the pair (min, max) from its smaller element, the other direction by
      // reciprocity (the sampling error is not multiplied by the ratio of the areas).
      row[j] = i < j ? fromSmallerElement(mesh, i, j, estimate).value
                     : fromSmallerElement(mesh, j, i, estimate).value * mesh.elements[j].area / ai;
    }
  };
}

}  // namespace

std::vector<std::string> rowProviderMethods() {
  return {"hemicube", "raycast"};
}

FormFactorRowProvider makeRowProvider(const std::string& method, const Mesh& mesh,
                                      const FormFactorOptions& options) {
  if (method == "hemicube") {
    const int resolution = std::max(2, options.hemicubeResolution);
    return hemicubeRows(mesh, resolution);
  }
  if (method == "raycast") return raycastRows(mesh, options);
  throw std::invalid_argument("form factors '" + method +
                              "' cannot be computed one row at a time (hemicube or raycast can)");
}

}  // namespace rt
