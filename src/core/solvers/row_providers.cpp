#include "core/solvers/row_providers.h"

#include <algorithm>
#include <stdexcept>

#include "core/formfactor/analytic.h"
#include "core/formfactor/hemicube.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/sampling.h"
#include "core/formfactor/visibility.h"

namespace rt {
namespace {

FormFactorRowProvider hemicubeRows(const Mesh& mesh, int resolution) {
  // The workspace is reused from shot to shot: no allocation after the first hemicube.
  auto workspace = std::make_shared<HemicubeWorkspace>();
  workspace->computeDepth = false;
  return [&mesh, resolution, workspace](int i, Eigen::VectorXd& row) {
    row.setZero(static_cast<Eigen::Index>(mesh.size()));
    renderHemicube(mesh, i, resolution, *workspace);
    accumulateHemicubeRow(workspace->faces, row.data());
  };
}

// The raycast method's estimator of F_ij: stratified points x on i, Lambert's exact formula from x to j, and
// where the shaft may be blocked a ray from x to a stratified point of j.
double raycastPair(const Mesh& mesh, const PairVisibility& visibility, int i, int j, int samples,
                   std::uint64_t seed) {
  const ElementPolygon a(mesh, i), b(mesh, j);
  const Vec3& normal = mesh.elements[i].normal;
  const bool occludable = visibility.mayBeOccluded(i, j);
  PairRandom random(seed, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j));
  const int shift = static_cast<int>(random.next() % static_cast<std::uint64_t>(samples));
  double sum = 0;
  for (int k = 0; k < samples; ++k) {
    const Vec2 s = jitteredSample(k, samples, random);
    const Vec3 x = pointOnPolygon(a.v.data(), a.count, s.x(), s.y());
    double value = pointToPolygonFormFactor(x, normal, b.v.data(), b.count);
    if (occludable && value > 0) {
      const Vec2 t = jitteredSample((k + shift) % samples, samples, random);
      const Vec3 y = pointOnPolygon(b.v.data(), b.count, t.x(), t.y());
      if (!visibility.rays().visible(x, y, i, j)) value = 0;
    }
    sum += value;
  }
  return sum / samples;
}

FormFactorRowProvider raycastRows(const Mesh& mesh, const FormFactorOptions& options) {
  auto visibility = std::make_shared<const PairVisibility>(mesh);
  const int samples = std::clamp(options.samples, 1, 1024);
  const std::uint64_t seed = options.seed;
  return [&mesh, visibility, samples, seed](int i, Eigen::VectorXd& row) {
    row.setZero(static_cast<Eigen::Index>(mesh.size()));
    const double ai = mesh.elements[i].area;
    for (int j = 0; j < static_cast<int>(mesh.size()); ++j) {
      if (j == i || !elementsFaceEachOther(mesh, i, j)) continue;
      // As in the matrix method: sampled on the smaller element, the other direction by reciprocity (the
      // sampling error is not multiplied by the ratio of the areas).
      const double aj = mesh.elements[j].area;
      const bool onI = i < j ? ai <= aj * (1 + 1e-9) : ai * (1 + 1e-9) < aj;  // the matrix method's choice
      row(j) = onI ? raycastPair(mesh, *visibility, i, j, samples, seed)
                   : raycastPair(mesh, *visibility, j, i, samples, seed) * aj / ai;
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
