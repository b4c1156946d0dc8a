// Adaptive subdivision (Cohen & Wallace, "Radiosity and Realistic Image Synthesis", ch. 8): solve, look at
// the radiosity differences between neighbouring elements, split where they are large, and compute only the
// form factors that the split made new. Also the uniform mesh, which is the same loop stopped after its first
// solve.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/formfactor/analytic.h"
#include "core/polygon.h"
#include "core/refine/dense_transfer.h"
#include "core/refine/piece_mesh.h"
#include "core/refine/refine_modes.h"

namespace rt {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Elements whose radiosity jumps against a neighbour's by more than the threshold, largest jumps first,
// limited to what the element budget allows and to elements whose children would not be smaller than minEdge.
// Variation of the direct illumination over an element: reflected direct radiosity rho E F V evaluated near
// its corners and at its centroid (closed-form F to each emitting patch, visibility by rays). This sees what
// neighbour jumps cannot: a gradient or a shadow edge inside an element that has no neighbour on its patch
// (the top of a Cornell block is one element at the start).
double directVariation(const Scene& scene, const Mesh& mesh, int e, const VisibilityOracle& visibility,
                       const std::vector<int>& emitters,
                       const std::vector<std::vector<SurfaceSample>>& lightSamples) {
  const Element& element = mesh.elements[e];
  if (emitters.empty() || (mesh.reflectance.row(e).array() <= 0).all()) return 0.0;
  std::vector<Vec3> points{element.centroid};
  for (int v : element.vertices)
    points.push_back(element.centroid + 0.9 * (mesh.vertices[v] - element.centroid));
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec3& x : points) {
    Eigen::RowVector3d direct = Eigen::RowVector3d::Zero();
    for (std::size_t l = 0; l < emitters.size(); ++l) {
      const Patch& light = scene.patches[emitters[l]];
      if (emitters[l] == element.patch) continue;
      const double F = pointToPolygonFormFactor(x, element.normal, light.vertices);
      if (F <= 0) continue;
      const double V = visibility.visibleFraction(x, lightSamples[l], element.patch, emitters[l]);
      direct += F * V * scene.materialOf(light).emission.matrix().transpose();
    }
    const double y = luminance((mesh.reflectance.row(e).array() * direct.array()).matrix());
    lo = std::min(lo, y);
    hi = std::max(hi, y);
  }
  return hi - lo;
}

std::vector<int> elementsToSplit(const Scene& scene, const Mesh& mesh, const RgbField& B,
                                 const std::vector<TVertex>& tVertices, const RefineOptions& options,
                                 const VisibilityOracle& visibility) {
  const std::size_t n = mesh.size();
  // The scale of "a large jump": the mean radiosity of the reflecting elements.
  const double threshold = options.gradientTolerance * meanReflectingLuminance(mesh, B);
  const auto neighbours = smoothNeighbours(scene, mesh, tVertices);
  std::vector<double> jump(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (int j : neighbours[i]) {
      const double d = std::abs(luminance(B.row(i)) - luminance(B.row(j)));
      jump[i] = std::max(jump[i], d);
    }
  std::vector<int> emitters;
  std::vector<std::vector<SurfaceSample>> lightSamples;
  for (std::size_t p = 0; p < scene.patches.size(); ++p)
    if (scene.materialOfPatch(static_cast<int>(p)).isEmitter()) {
      emitters.push_back(static_cast<int>(p));
      lightSamples.push_back(stratifiedSamples(scene.patches[p].vertices, 3));
    }
  for (std::size_t i = 0; i < n; ++i)
    jump[i] = std::max(jump[i],
                       directVariation(scene, mesh, static_cast<int>(i), visibility, emitters, lightSamples));
  std::vector<int> marked;
  for (std::size_t i = 0; i < n; ++i)
    if (jump[i] > threshold && maxEdgeLength(mesh.polygon(static_cast<int>(i))) >= 2 * options.minEdge)
      marked.push_back(static_cast<int>(i));
  // Under a tight budget, split where the error is largest: a jump over a large element costs more than the
  // same jump over a small one (the L2 error of a constant element grows like jump x sqrt(area)).
  auto priority = [&](int e) { return jump[e] * std::sqrt(mesh.elements[e].area); };
  std::sort(marked.begin(), marked.end(), [&](int a, int b) { return priority(a) > priority(b); });
  const std::size_t room = options.maxElements > static_cast<int>(n) ? (options.maxElements - n) / 3 : 0;
  if (marked.size() > room) marked.resize(room);
  std::sort(marked.begin(), marked.end());
  return marked;
}

RefinedSolution refineLoop(const Scene& scene, const RefineOptions& options, Progress& progress, int passes) {
  const auto start = Clock::now();
  RefinedSolution solution;
  solution.stats.mode = options.mode;
  const VisibilityOracle visibility(scene);
  TransferOptions transfer;
  transfer.visibilitySamples = options.visibilitySamples;

  MeshOptions meshOptions;
  meshOptions.mode = MeshOptions::Mode::MaxEdge;
  meshOptions.maxEdge = options.initialMaxEdge;
  Mesh mesh = buildMesh(scene, meshOptions);
  solution.stats.initialElements = mesh.size();
  std::vector<int> level(mesh.size(), 0);
  std::vector<int> oldIndex;
  FormFactorMatrix F;
  RgbField B = mesh.emission;

  for (int pass = 0;; ++pass) {
    RefinePass record;
    record.elements = mesh.size();
    const auto passStart = Clock::now();
    std::vector<Polygon> storage;
    const std::vector<SurfacePiece> pieces = piecesOfMesh(mesh, storage);
    const auto ffStart = Clock::now();
    F = updateFormFactors(F, oldIndex, pieces, visibility, transfer, progress,
                          "form factors, pass " + std::to_string(pass + 1), record.pairsComputed);
    solution.stats.formFactorSeconds += secondsSince(ffStart);
    const auto solveStart = Clock::now();
    record.sweeps = gatherSolve(RadiositySystem::fromMesh(mesh, F), B, options.solverTolerance,
                                options.maxSweeps, progress);
    solution.stats.solveSeconds += secondsSince(solveStart);
    solution.stats.pairsComputed += record.pairsComputed;
    std::vector<TVertex> tVertices = findTVertices(mesh);

    std::vector<int> split;
    if (pass + 1 < passes) split = elementsToSplit(scene, mesh, B, tVertices, options, visibility);
    record.split = split.size();
    record.seconds = secondsSince(passStart);
    solution.stats.passes.push_back(record);
    if (split.empty()) {
      solution.tVertices = std::move(tVertices);
      break;
    }

    // Children replace their parent in place of order; they start from the parent's radiosity.
    std::vector<Polygon> nextPieces;
    std::vector<int> nextPatch, nextLevel, nextOld;
    std::vector<Eigen::RowVector3d> nextB;
    std::size_t s = 0;
    for (std::size_t e = 0; e < mesh.size(); ++e) {
      const bool splitThis = s < split.size() && split[s] == static_cast<int>(e);
      if (splitThis) ++s;
      const Polygon polygon = mesh.polygon(static_cast<int>(e));
      const std::vector<Polygon> parts = splitThis ? splitInFour(polygon) : std::vector<Polygon>{polygon};
      for (const Polygon& part : parts) {
        nextPieces.push_back(part);
        nextPatch.push_back(mesh.elements[e].patch);
        nextLevel.push_back(level[e] + (splitThis ? 1 : 0));
        nextOld.push_back(splitThis ? -1 : static_cast<int>(e));
        nextB.push_back(B.row(static_cast<Eigen::Index>(e)));
      }
    }
    mesh = meshFromPieces(scene, nextPieces, nextPatch);
    level = std::move(nextLevel);
    oldIndex = std::move(nextOld);
    B.resize(static_cast<Eigen::Index>(nextB.size()), 3);
    for (std::size_t k = 0; k < nextB.size(); ++k) B.row(static_cast<Eigen::Index>(k)) = nextB[k];
  }

  solution.mesh = std::move(mesh);
  solution.B = std::move(B);
  solution.elementLevel = std::move(level);
  solution.stats.elements = solution.mesh.size();
  for (int l : solution.elementLevel) solution.stats.maxLevel = std::max(solution.stats.maxLevel, l);
  solution.stats.tVertices = solution.tVertices.size();
  solution.stats.raysCast = visibility.raysCast();
  solution.stats.seconds = secondsSince(start);
  return solution;
}

}  // namespace

RefinedSolution solveUniform(const Scene& scene, const RefineOptions& options, Progress& progress) {
  return refineLoop(scene, options, progress, 1);
}

RefinedSolution solveAdaptive(const Scene& scene, const RefineOptions& options, Progress& progress) {
  return refineLoop(scene, options, progress, options.maxPasses);
}

}  // namespace rt
