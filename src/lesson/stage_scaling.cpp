// The scaling stage: why the dense method stops at a few ten thousand elements and what replaces it. For
// each of the step's `subdivisions` the mesh's F is computed with the step's method (its n^2 doubles and its
// time) and the same mesh is solved by hierarchical-clustering (its links, nodes and counted bytes); local
// lines, which needs no F at all, is run on the step's own mesh with each `sweep` value as rays per element,
// and the standard error it reports is fitted against the rays. The cluster tree of the step's mesh is cut
// at `cluster-depth` so that the figure can show what one link stands for.
#include <unistd.h>

#include <cmath>
#include <memory>

#include "core/solvers/cluster_tree.h"
#include "lesson/scaling_data.h"
#include "lesson/step_settings.h"
#include "lesson/step_stages.h"

namespace rt::lesson::detail {
namespace {

double physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize) : 0.0;
}

void checkCancelled(const Progress& progress) {
  if (progress.cancelled()) throw Cancelled();
}

// The boxes of the nodes `depth` levels below the root; a leaf that ends higher up stands for itself.
void collectBoxes(const ClusterTree& tree, int node, int depth, std::vector<ClusterBox>& boxes) {
  const ClusterNode& k = tree.node(node);
  if (depth == 0 || k.leaf()) {
    boxes.push_back({k.box.min(), k.box.max()});
    return;
  }
  collectBoxes(tree, k.left, depth - 1, boxes);
  collectBoxes(tree, k.right, depth - 1, boxes);
}

SolveOutcome solveWith(StageContext& c, const Mesh& mesh, const std::string& solver, int raysPerIteration) {
  SolverOptions options = solverOptionsFor(c.parameters);
  if (raysPerIteration > 0) options.raysPerIteration = raysPerIteration;
  return solveRadiosity(RadiositySystem::fromGeometry(mesh), solver, options, false, c.progress);
}

// The dense matrix against the clustering solver on each of the step's meshes.
void measureMeshes(StageContext& c, ScalingData& data) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  auto& v = r.values;
  std::vector<double> n, links, seconds;
  for (std::size_t k = 0; k < p.subdivisions.size(); ++k) {
    c.progress.report(0.6 * static_cast<double>(k) / static_cast<double>(p.subdivisions.size()), "meshes");
    MeshOptions o;
    o.mode = MeshOptions::Mode::Count;
    o.count = p.subdivisions[k];
    const Mesh mesh = buildMesh(r.scene, o);
    ScalingPoint point;
    point.subdivide = p.subdivisions[k];
    point.elements = static_cast<long>(mesh.size());
    const double count = static_cast<double>(mesh.size());
    point.denseBytes = count * count * static_cast<double>(sizeof(double));
    FormFactorStats stats;
    c.formFactors(mesh, r.method, "subdivisions", stats);
    point.formFactorSeconds = stats.seconds;
    checkCancelled(c.progress);
    const SolveOutcome clustered = solveWith(c, mesh, "hierarchical-clustering", 0);
    point.links = clustered.links;
    point.nodes = clustered.nodes;
    point.clusterBytes = static_cast<double>(clustered.memoryBytes);
    point.clusterSeconds = clustered.seconds;
    checkCancelled(c.progress);

    const std::string i = "[" + std::to_string(k) + "]";
    v["elements" + i] = count;
    v["pairs" + i] = count * count;
    v["bytes.dense" + i] = point.denseBytes;
    v["seconds.formfactors" + i] = point.formFactorSeconds;
    v["links" + i] = static_cast<double>(point.links);
    v["nodes" + i] = static_cast<double>(point.nodes);
    v["links-per-element" + i] = static_cast<double>(point.links) / count;
    v["bytes.clustering" + i] = point.clusterBytes;
    v["seconds.clustering" + i] = point.clusterSeconds;
    n.push_back(count);
    links.push_back(static_cast<double>(point.links));
    seconds.push_back(point.formFactorSeconds);
    data.points.push_back(point);
  }
  data.linksSlope = logLogSlope(n, links);
  data.formFactorSlope = logLogSlope(n, seconds);
  v["links-slope"] = data.linksSlope;
  v["time-slope.formfactors"] = data.formFactorSlope;

  // Where F stops fitting in this machine's memory, and the time F would take there, extrapolated from the
  // largest mesh along n^2 (every pair is computed).
  data.memoryBytes = physicalMemoryBytes();
  data.elementsThatFit = std::sqrt(data.memoryBytes / static_cast<double>(sizeof(double)));
  v["memory"] = data.memoryBytes;
  v["memory.gib"] = data.memoryBytes / (1024.0 * 1024.0 * 1024.0);
  v["elements.fit"] = data.elementsThatFit;
  const ScalingPoint& last = data.points.back();
  const double ratio = data.elementsThatFit / static_cast<double>(last.elements);
  v["seconds.formfactors.fit"] = last.formFactorSeconds * ratio * ratio;
  v["minutes.formfactors.fit"] = last.formFactorSeconds * ratio * ratio / 60.0;
}

// Local lines on the step's mesh: no F, and its reported noise against the rays.
void measureNoise(StageContext& c, ScalingData& data) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  std::vector<double> rays, errors;
  const double elements = static_cast<double>(r.mesh.size());
  for (std::size_t k = 0; k < p.sweep.size(); ++k) {
    c.progress.report(0.6 + 0.35 * static_cast<double>(k) / static_cast<double>(p.sweep.size()), "rays");
    const int perIteration = static_cast<int>(std::min(2e9, elements * p.sweep[k]));
    const SolveOutcome lines = solveWith(c, r.mesh, "local-lines", perIteration);
    const SolverNoisePoint point{static_cast<double>(lines.rays) / elements, lines.standardError};
    const std::string i = "[" + std::to_string(k) + "]";
    r.values["rays-per-element" + i] = point.raysPerElement;
    r.values["standard-error" + i] = point.standardError;
    rays.push_back(point.raysPerElement);
    errors.push_back(point.standardError);
    data.noise.push_back(point);
    r.B = lines.B;
    checkCancelled(c.progress);
  }
  data.noiseSlope = logLogSlope(rays, errors);
  r.values["noise-slope"] = data.noiseSlope;
}

}  // namespace

void computeScaling(StageContext& c) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  // Each part runs only when its list is given, so that a step about noise does not pay for the meshes.
  if (p.subdivisions.empty() && p.sweep.empty())
    c.fail("stage",
           "a scaling step needs `subdivisions` (meshes to measure), `sweep` (rays per element) or both");
  auto data = std::make_shared<ScalingData>();
  r.method = c.method();
  if (!p.subdivisions.empty()) measureMeshes(c, *data);
  if (!p.sweep.empty()) measureNoise(c, *data);

  const ClusterTree tree(r.mesh, r.mesh.reflectance);
  data->clusterDepth = p.clusterDepth;
  collectBoxes(tree, 0, p.clusterDepth, data->boxes);
  r.values["cluster-depth"] = p.clusterDepth;
  r.values["clusters"] = static_cast<double>(data->boxes.size());
  r.values["nodes"] = static_cast<double>(tree.size());
  r.scaling = std::move(data);
}

}  // namespace rt::lesson::detail
