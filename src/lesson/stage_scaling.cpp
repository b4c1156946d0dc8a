// The scaling stage: why the dense method stops at a few ten thousand elements and what replaces it. For
// each of the step's `subdivisions` the mesh's F is computed with the step's method (its n^2 doubles and its
// time), the system is solved directly (LU, n^3) and by Jacobi (sweeps of n^2 each), and the same mesh is
// solved by hierarchical-clustering (its links, nodes and counted bytes); local lines, which needs no F at
// all, is run on the step's own mesh with each `sweep` value as rays per element, and the standard error it
// reports is fitted against the rays. A step that names a `solver` solves its own mesh with it, without F,
// so that a scene far too large for F (the museum) shows what the solver keeps instead. The cluster tree of
// the step's mesh is cut at `cluster-depth` so that the figure can show what one link stands for. The files
// of `scenes` (one scene written at several sizes) are each solved by hierarchical-clustering alone, no F, so
// that their links can be counted against n where a dense F could never be stored.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>

#include "core/assembly.h"
#include "core/solvers/cluster_tree.h"
#include "lesson/scaling_data.h"
#include "lesson/step_settings.h"
#include "lesson/step_stages.h"
#include "lesson/value_parsing.h"

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

SolveOutcome solveWith(StageContext& c, const RadiositySystem& system, const std::string& solver,
                       int raysPerIteration) {
  SolverOptions options = solverOptionsFor(c.parameters);
  if (raysPerIteration > 0) options.raysPerIteration = raysPerIteration;
  return solveRadiosity(system, solver, options, false, c.progress);
}

SolveOutcome solveWith(StageContext& c, const Mesh& mesh, const std::string& solver, int raysPerIteration) {
  return solveWith(c, RadiositySystem::fromGeometry(mesh), solver, raysPerIteration);
}

// The dense method's solve on one mesh: Gaussian elimination (n^3 / 3 multiply-adds per factorisation) and
// Jacobi, whose sweeps cost n^2 each and whose number of sweeps depends on the reflectances, not on n.
void measureSolves(StageContext& c, const Mesh& mesh, const FormFactorMatrix& F, ScalingPoint& point) {
  const RadiositySystem system = RadiositySystem::fromMesh(mesh, F);
  point.directSeconds = solveWith(c, system, "direct", 0).seconds;
  checkCancelled(c.progress);
  const SolveOutcome jacobi = solveWith(c, system, "jacobi", 0);
  point.jacobiSweeps = jacobi.iterations;
  point.sweepSeconds = jacobi.seconds / std::max(1, jacobi.iterations);
  point.fill = fillFraction(F);
}

// The dense matrix against the clustering solver on each of the step's meshes.
void measureMeshes(StageContext& c, ScalingData& data) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  auto& v = r.values;
  std::vector<double> n, links, seconds, direct, sweep;
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
    const auto F = c.formFactors(mesh, r.method, "subdivisions", stats);
    point.formFactorSeconds = stats.seconds;
    checkCancelled(c.progress);
    measureSolves(c, mesh, *F, point);
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
    v["seconds.direct" + i] = point.directSeconds;
    v["seconds.sweep" + i] = point.sweepSeconds;
    v["iterations.jacobi" + i] = point.jacobiSweeps;
    v["fill" + i] = point.fill;
    v["links" + i] = static_cast<double>(point.links);
    v["nodes" + i] = static_cast<double>(point.nodes);
    v["links-per-element" + i] = static_cast<double>(point.links) / count;
    v["bytes.clustering" + i] = point.clusterBytes;
    v["seconds.clustering" + i] = point.clusterSeconds;
    n.push_back(count);
    links.push_back(static_cast<double>(point.links));
    seconds.push_back(point.formFactorSeconds);
    direct.push_back(std::max(point.directSeconds, 1e-9));
    sweep.push_back(std::max(point.sweepSeconds, 1e-9));
    data.points.push_back(point);
  }
  data.linksSlope = logLogSlope(n, links);
  data.formFactorSlope = logLogSlope(n, seconds);
  v["links-slope"] = data.linksSlope;
  v["time-slope.formfactors"] = data.formFactorSlope;
  data.directSlope = logLogSlope(n, direct);
  data.sweepSlope = logLogSlope(n, sweep);
  v["time-slope.direct"] = data.directSlope;
  v["time-slope.sweep"] = data.sweepSlope;

  // The time F and the direct solve would take where F fills the memory, extrapolated from the largest
  // mesh along n^2 (every pair is computed) and n^3 (elimination).
  const ScalingPoint& last = data.points.back();
  const double ratio = data.elementsThatFit / static_cast<double>(last.elements);
  v["seconds.formfactors.fit"] = last.formFactorSeconds * ratio * ratio;
  v["minutes.formfactors.fit"] = last.formFactorSeconds * ratio * ratio / 60.0;
  v["hours.direct.fit"] = last.directSeconds * ratio * ratio * ratio / 3600.0;
}

// The step's own mesh: what its dense F would take, against this machine's memory, and with a `solver`
// written in the step, what that solver keeps instead (it runs without F, so it must be one that needs none).
void measureOwnMesh(StageContext& c, ScalingData& data) {
  StepResult& r = c.result;
  auto& v = r.values;
  const double count = static_cast<double>(r.mesh.size());
  data.memoryBytes = physicalMemoryBytes();
  data.elementsThatFit = std::sqrt(data.memoryBytes / static_cast<double>(sizeof(double)));
  v["memory"] = data.memoryBytes;
  v["memory.gib"] = data.memoryBytes / (1024.0 * 1024.0 * 1024.0);
  v["elements.fit"] = data.elementsThatFit;
  v["pairs.mesh"] = count * count;
  v["bytes.dense.mesh"] = count * count * static_cast<double>(sizeof(double));
  v["gib.dense.mesh"] = v["bytes.dense.mesh"] / (1024.0 * 1024.0 * 1024.0);
  if (!c.step.fields.count("solver")) return;
  const SolveOutcome own = solveWith(c, r.mesh, c.parameters.solver, 0);
  if (own.status == SolverStatus::InvalidInput)
    c.fail("solver", "a scaling step solves its own mesh without F: '" + c.parameters.solver +
                         "' needs one (use hierarchical-clustering or a local-lines solver)");
  r.B = own.B;
  v["links"] = static_cast<double>(own.links);
  v["links-per-element"] = static_cast<double>(own.links) / count;
  v["pairs-per-link"] = own.links > 0 ? count * count / static_cast<double>(own.links) : 0.0;
  v["bytes.solver"] = static_cast<double>(own.memoryBytes);
  v["dense-over-solver"] =
      own.memoryBytes > 0 ? v["bytes.dense.mesh"] / static_cast<double>(own.memoryBytes) : 0.0;
  v["seconds.solver"] = own.seconds;
  v["iterations"] = own.iterations;
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

// A scene's name as placeholders spell it: "Factory hall" -> "factory-hall".
std::string placeholderKey(const std::string& name) {
  std::string key;
  for (const char ch : name)
    key += std::isalnum(static_cast<unsigned char>(ch)) ? static_cast<char>(std::tolower(ch)) : '-';
  return key;
}

// The step's `scenes`: each file meshed as the step's own scene and solved by hierarchical-clustering; the
// files are grouped by the scene's name and ordered by n within a group.
void measureScenes(StageContext& c, ScalingData& data) {
  auto& v = c.result.values;
  const std::vector<std::string> files = parseList(c.parameters.scenes);
  for (std::size_t k = 0; k < files.size(); ++k) {
    c.progress.report(static_cast<double>(k) / static_cast<double>(files.size()), "scenes");
    const Scene* scene = nullptr;
    try {
      scene = &c.runner.scene(files[k]);
    } catch (const InputError& e) {
      c.fail("scenes", "the scene '" + files[k] + "' does not load: " + e.what());
    }
    const std::string name = scene->name.empty() ? files[k] : scene->name;
    auto series = std::find_if(data.sceneLinks.begin(), data.sceneLinks.end(),
                               [&](const SceneLinksSeries& s) { return s.name == name; });
    if (series == data.sceneLinks.end())
      series = data.sceneLinks.insert(data.sceneLinks.end(),
                                      SceneLinksSeries{name, placeholderKey(name), {}, 0.0});
    const Mesh mesh = buildMesh(*scene, c.meshOptions);
    const SolveOutcome clustered = solveWith(c, mesh, "hierarchical-clustering", 0);
    if (clustered.status == SolverStatus::InvalidInput)
      c.fail("scenes", "hierarchical-clustering cannot solve '" + files[k] + "' (does it emit light?)");
    series->points.push_back(
        SceneLinksPoint{files[k], static_cast<long>(mesh.size()), clustered.links, clustered.seconds});
    checkCancelled(c.progress);
  }
  for (SceneLinksSeries& series : data.sceneLinks) {
    std::sort(series.points.begin(), series.points.end(),
              [](const SceneLinksPoint& a, const SceneLinksPoint& b) { return a.elements < b.elements; });
    std::vector<double> n, links;
    for (std::size_t k = 0; k < series.points.size(); ++k) {
      const SceneLinksPoint& p = series.points[k];
      const double count = static_cast<double>(p.elements);
      const std::string at = "." + series.key + "[" + std::to_string(k) + "]";
      v["elements" + at] = count;
      v["pairs" + at] = count * count;
      v["links" + at] = static_cast<double>(p.links);
      v["links-per-element" + at] = static_cast<double>(p.links) / count;
      v["pairs-per-link" + at] = p.links > 0 ? count * count / static_cast<double>(p.links) : 0.0;
      v["seconds" + at] = p.seconds;
      n.push_back(count);
      links.push_back(static_cast<double>(std::max(1L, p.links)));
    }
    series.slope = n.size() >= 2 ? logLogSlope(n, links) : 0.0;
    v["links-slope." + series.key] = series.slope;
  }
}

// What the measurements leave in the result, kept by the runner under everything they depend on.
struct ScalingMeasured {
  std::map<std::string, double> values;
  RgbField B;
  ScalingData data;
};

}  // namespace

void computeScaling(StageContext& c) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  // Each part runs only when its list is given, so that a step about noise does not pay for the meshes.
  if (p.subdivisions.empty() && p.sweep.empty() && parseList(p.scenes).empty() &&
      !c.step.fields.count("solver"))
    c.fail("stage",
           "a scaling step needs `subdivisions` (meshes to measure), `sweep` (rays per element), `scenes` "
           "(scene files whose links are counted) or a `solver` for its own mesh");
  auto data = std::make_shared<ScalingData>();
  r.method = c.method();
  // The cluster depth only cuts the tree that the figure draws: a reader who changes it gets the kept
  // measurements (their times included) instead of waiting for every mesh to be timed again.
  const std::string key = "scaling measurements|" + picturesKey(c, {"cluster-depth"});
  if (const auto kept = c.runner.keptPictures<ScalingMeasured>(key)) {
    r.values = kept->values;
    r.B = kept->B;
    *data = kept->data;
  } else {
    measureOwnMesh(c, *data);
    if (!p.subdivisions.empty()) measureMeshes(c, *data);
    if (!p.sweep.empty()) measureNoise(c, *data);
    if (!parseList(p.scenes).empty()) measureScenes(c, *data);
    c.runner.keepPictures(key,
                          std::make_shared<const ScalingMeasured>(ScalingMeasured{r.values, r.B, *data}));
  }

  const ClusterTree tree(r.mesh, r.mesh.reflectance);
  data->clusterDepth = p.clusterDepth;
  collectBoxes(tree, 0, p.clusterDepth, data->boxes);
  r.values["cluster-depth"] = p.clusterDepth;
  r.values["clusters"] = static_cast<double>(data->boxes.size());
  r.values["nodes"] = static_cast<double>(tree.size());
  r.scaling = std::move(data);
}

}  // namespace rt::lesson::detail
