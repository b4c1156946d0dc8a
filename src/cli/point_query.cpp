#include "cli/point_query.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace rt::cli {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The mesh error of the fine solution, estimated from its difference to the coarse one's at each point. With
// the same seed both passes draw the same rays, so the difference is the meshes' and not noise. If the error
// falls like h^p in the element size h, e(h) = (e(2h) - e(h)) / (2^p - 1): at most the difference for p >= 1
// (piecewise-constant radiosity where the light is smooth), at most twice it for p >= 0.58 (along shadow
// boundaries the elements straddle, where it converges more slowly). Twice the difference is written.
void addMeshErrors(std::vector<PointEstimate>& fine, const std::vector<PointEstimate>& coarse) {
  constexpr double kSlowestOrderFactor = 2;
  for (std::size_t p = 0; p < fine.size(); ++p) {
    fine[p].HMeshError = kSlowestOrderFactor * (fine[p].H - coarse[p].H).abs();
    fine[p].BMeshError = kSlowestOrderFactor * (fine[p].B - coarse[p].B).abs();
  }
}

// The mesh with elements half the size (twice the splits).
MeshOptions finerMesh(const MeshOptions& mesh) {
  MeshOptions finer = mesh;
  if (mesh.mode == MeshOptions::Mode::MaxEdge) finer.maxEdge = mesh.maxEdge / 2;
  if (mesh.mode == MeshOptions::Mode::Count) finer.count = 2 * mesh.count;
  return finer;
}

// A solution and its second pass, kept so that more gather rays reuse the solve.
struct SolvedMesh {
  Pipeline pipeline;
  Solution solution;
  std::unique_ptr<TwoPass> twoPass;
  std::vector<PointEstimate> pilot;  // at kPilotRays
};

std::unique_ptr<SolvedMesh> solve(const Scene& scene, const TracingScene& tracing, const MeshOptions& mesh,
                                  const PointQuery& query) {
  const auto start = std::chrono::steady_clock::now();
  auto solved = std::make_unique<SolvedMesh>();
  solved->solution = solveOnMesh(scene, mesh, query.solution, solved->pipeline);
  solved->twoPass =
      std::make_unique<TwoPass>(tracing, solved->solution.mesh, solved->solution.outcome.B,
                                solved->solution.formFactors ? &solved->solution.formFactors->F : nullptr);
  std::fprintf(stderr, "two-pass: solution (%zu elements) %.2f s\n", solved->solution.mesh.size(),
               secondsSince(start));
  return solved;
}

std::vector<PointEstimate> estimateOn(const SolvedMesh& solved, const PointQuery& query, int gatherRays,
                                      const std::vector<SurfacePoint>& points) {
  const auto start = std::chrono::steady_clock::now();
  TwoPassOptions options = query.twoPass;
  options.seed = query.solution.seed;
  if (gatherRays > 0) options.gatherRays = gatherRays;
  std::vector<PointEstimate> estimates = solved.twoPass->estimate(points, options);
  std::fprintf(stderr, "two-pass: %zu points, direct light and gather (%d rays) %.2f s\n", points.size(),
               options.gatherRays, secondsSince(start));
  return estimates;
}

// The RMS over the points and channels of (a - b) / a (points with a = 0 left out).
double relativeRmsDifference(const std::vector<PointEstimate>& a, const std::vector<PointEstimate>& b) {
  double squares = 0;
  int values = 0;
  for (std::size_t p = 0; p < a.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      if (!(a[p].H(c) > 0)) continue;
      squares += std::pow((a[p].H(c) - b[p].H(c)) / a[p].H(c), 2);
      ++values;
    }
  return values ? std::sqrt(squares / values) : 0.0;
}

// The mesh's share of the target: the errors add in quadrature, and the mesh, whose every refinement
// quadruples the elements and multiplies the form factors' cost by about 16, gets at most 0.6 of it, so that
// the noise, which costs rays, keeps at least 0.8 (0.6^2 + 0.8^2 = 1).
constexpr double kMeshShare = 0.6;
constexpr int kPilotRays = 1024;    // 64 rays per batch: enough to measure the standard errors
constexpr int kMaxRefinements = 2;  // the mesh's elements at most 16 times as many
constexpr int kMaxGatherRays = 1 << 22;

// Richardson's estimate of the error of the solution on mesh h from the solutions on h, 2h and 4h (the same
// seed and rays, so that their differences are the meshes'): if the error falls like h^p, the differences
// H(2h) - H(h) and H(4h) - H(2h) are in the ratio 2^p, and the error left on h is (H(2h) - H(h)) / (2^p - 1).
// The order p is fitted once over all the points (a point's own ratio is too noisy) and taken as at most 1,
// so that the estimate is never below the difference itself: along shadow boundaries, which the elements
// straddle, the error falls more slowly than over the smooth rest. Returns the factor on the difference.
double richardsonFactor(const SolvedMesh& h, const SolvedMesh& h2, const SolvedMesh& h4, double& order) {
  const double fine = relativeRmsDifference(h.pilot, h2.pilot);
  const double coarse = relativeRmsDifference(h2.pilot, h4.pilot);
  order = fine > 0 && coarse > fine ? std::log2(coarse / fine) : 1.0;
  return std::max(1.0, 1.0 / (std::pow(2.0, order) - 1.0));
}

void setMeshErrors(std::vector<PointEstimate>& estimates, const SolvedMesh& h, const SolvedMesh& h2,
                   double factor) {
  for (std::size_t p = 0; p < estimates.size(); ++p) {
    estimates[p].HMeshError = factor * (h.pilot[p].H - h2.pilot[p].H).abs();
    estimates[p].BMeshError = factor * (h.pilot[p].B - h2.pilot[p].B).abs();
  }
}

}  // namespace

double parseTargetError(const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return -1;
  }
  const std::string rest = text.substr(used);
  if (rest == "%")
    value /= 100;
  else if (!rest.empty())
    return -1;
  return value > 0 && value < 1 ? value : -1;
}

std::vector<PointEstimate> twoPassEstimates(const Scene& scene, const TracingScene& tracing,
                                            const MeshOptions& mesh, const PointQuery& query,
                                            const std::vector<SurfacePoint>& points) {
  return estimateOn(*solve(scene, tracing, mesh, query), query, 0, points);
}

std::vector<PointEstimate> estimatesWithMeshError(const Scene& scene, const TracingScene& tracing,
                                                  const MeshOptions& mesh, const PointQuery& query,
                                                  const std::vector<SurfacePoint>& points) {
  std::vector<PointEstimate> estimates = twoPassEstimates(scene, tracing, mesh, query, points);
  MeshOptions coarser;
  if (query.meshError && coarserMesh(mesh, coarser)) {
    std::cerr << "mesh error: the same points on a mesh with elements twice the size\n";
    addMeshErrors(estimates, twoPassEstimates(scene, tracing, coarser, query, points));
  } else if (query.meshError) {
    std::cerr << "mesh error: not estimated (one element per polygon cannot be made coarser)\n";
  }
  return estimates;
}

double relativeRms(const std::vector<PointEstimate>& estimates, Rgb PointEstimate::*part, double factor) {
  double squares = 0;
  int values = 0;
  for (const PointEstimate& e : estimates)
    for (int c = 0; c < 3; ++c) {
      if (!(e.H(c) > 0)) continue;
      squares += std::pow(factor * (e.*part)(c) / e.H(c), 2);
      ++values;
    }
  return values ? std::sqrt(squares / values) : 0.0;
}

std::vector<PointEstimate> estimatesForTarget(const Scene& scene, const TracingScene& tracing,
                                              const MeshOptions& mesh, const PointQuery& query,
                                              const std::vector<SurfacePoint>& points) {
  const double target = query.targetError;
  // The meshes h, 2h and 4h, each with its pilot pass; levels[0] is the finest.
  std::vector<std::unique_ptr<SolvedMesh>> levels;
  MeshOptions options = mesh;
  for (int k = 0; k < 3; ++k) {
    levels.push_back(solve(scene, tracing, options, query));
    levels.back()->pilot = estimateOn(*levels.back(), query, kPilotRays, points);
    MeshOptions coarser;
    if (k < 2 && !coarserMesh(options, coarser)) break;
    options = coarser;
  }
  if (levels.size() < 3)
    std::cerr << "target error: the mesh cannot be made coarser twice, so its error is not estimated\n";
  MeshOptions chosen = mesh;
  double order = 1, factor = 1, meshPart = 0;
  for (int refinements = 0; levels.size() == 3; ++refinements) {
    factor = richardsonFactor(*levels[0], *levels[1], *levels[2], order);
    meshPart = factor * relativeRmsDifference(levels[0]->pilot, levels[1]->pilot);
    if (meshPart <= kMeshShare * target || refinements == kMaxRefinements) break;
    std::fprintf(stderr,
                 "target error: the mesh's error %.3g %% RMS (order %.2f) is over %.3g %%: elements halved\n",
                 100 * meshPart, order, 100 * kMeshShare * target);
    chosen = finerMesh(chosen);
    levels.pop_back();
    levels.insert(levels.begin(), solve(scene, tracing, chosen, query));
    levels.front()->pilot = estimateOn(*levels.front(), query, kPilotRays, points);
  }
  // The rest of the target, in quadrature, goes to the noise, whose standard error falls as 1/sqrt(rays);
  // with a mesh still over its share, at least a tenth of the target.
  const double noiseTarget =
      std::max(0.1 * target, std::sqrt(std::max(0.0, target * target - meshPart * meshPart)));
  const double pilotNoise = relativeRms(levels[0]->pilot, &PointEstimate::HError);
  const int rays = static_cast<int>(std::clamp(std::ceil(kPilotRays * std::pow(pilotNoise / noiseTarget, 2)),
                                               double(kPilotRays), double(kMaxGatherRays)));
  std::vector<PointEstimate> estimates =
      rays > kPilotRays ? estimateOn(*levels[0], query, rays, points) : levels[0]->pilot;
  if (levels.size() == 3) setMeshErrors(estimates, *levels[0], *levels[1], factor);
  const double noise = relativeRms(estimates, &PointEstimate::HError);
  std::fprintf(
      stderr,
      "target error %.3g %% RMS: %zu elements, %d gather rays, %d secondary rays; estimated mesh "
      "error %.3g %% (order %.2f), standard error %.3g %%, together %.3g %% RMS; per point, H_r_estimate... "
      "is two standard errors plus the mesh error\n",
      100 * target, levels[0]->solution.mesh.size(), rays, query.twoPass.nearRays, 100 * meshPart, order,
      100 * noise, 100 * std::hypot(meshPart, noise));
  return estimates;
}

}  // namespace rt::cli
