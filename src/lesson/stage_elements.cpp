// The linear basis in the lessons: a solve step with `basis: linear` solves the nodes' system (core/basis)
// through the runner's pipeline, and the elements stage measures both bases against a fine reference on a
// sweep of meshes, over the scene and over the highlighted surfaces, with the fitted convergence orders.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>

#include "core/basis/linear_kernel.h"
#include "core/basis/radiosity_field.h"
#include "core/pipeline/linear_solve.h"
#include "core/power_law.h"
#include "lesson/elements_data.h"
#include "lesson/step_settings.h"
#include "lesson/step_stages.h"

namespace rt::lesson::detail {
namespace {

std::shared_ptr<const LinearKernel> kernelFor(StageContext& c, const Mesh& mesh) {
  if (const std::string problem = linearBasisProblem(c.parameters.solver, c.method()); !problem.empty())
    c.fail("basis", problem);
  try {
    return c.runner.pipeline().linearKernel(mesh, c.optionsFor(c.method(), 0), c.progress);
  } catch (const InputError& e) {
    c.fail("basis", e.message());
  }
}

// The patches of the surface called `name`.
std::function<bool(int)> surfacePatches(const Scene& scene, const std::string& name) {
  return [&scene, name](int patch) {
    return scene.surfaces[static_cast<std::size_t>(scene.patches[static_cast<std::size_t>(patch)].surface)]
               .name == name;
  };
}

}  // namespace

void computeSolveLinear(StageContext& c) {
  StepResult& r = c.result;
  const auto kernel = kernelFor(c, r.mesh);
  RgbField nodal;
  // Not replayable: the app replays per-element iterations, and these are per node.
  r.runs.push_back(runSolver(c, c.parameters.solver, linearSystem(*kernel), nodal, c.parameters.solver));
  r.B = kernel->basis.elementAverages(nodal);
  r.corners = kernel->basis.cornerValues(nodal);
  r.formFactorStats = kernel->stats;
  r.method = c.method();
  for (const char* key : {"iterations", "residual", "seconds", "converged"})
    r.values[key] = r.values[std::string(key) + "." + c.parameters.solver];
  r.values["nodes"] = static_cast<double>(kernel->basis.size());
  r.values["elements"] = static_cast<double>(r.mesh.size());
  r.values["seconds.kernel"] = kernel->stats.seconds;
  const double tolerance = c.optionsFor(c.method(), 0).tolerance;
  r.values["kernel-tolerance"] = tolerance > 0 ? tolerance : kLinearKernelTolerance;
}

void computeElements(StageContext& c) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  if (p.subdivisions.size() < 2) c.fail("subdivisions", "an elements step needs at least two `subdivisions`");
  if (!p.subdivide) c.fail("subdivide", "an elements step needs `subdivide`: the reference's mesh");
  std::vector<int> subdivisions = p.subdivisions;
  int referenceSubdivide = *p.subdivide;
  if (c.runner.options().quick) {
    // Quick runs cap `subdivide`: the sweep keeps its length (the text names its entries) below it.
    for (std::size_t k = 0; k < subdivisions.size(); ++k) subdivisions[k] = static_cast<int>(k) + 1;
    referenceSubdivide = std::max(referenceSubdivide, static_cast<int>(subdivisions.size()) + 1);
    if (referenceSubdivide != *p.subdivide) {
      MeshOptions o;
      o.mode = MeshOptions::Mode::Count;
      o.count = referenceSubdivide;
      r.mesh = buildMesh(r.scene, o);
    }
  }
  for (const int n : subdivisions)
    if (n >= referenceSubdivide)
      c.fail("subdivisions", "every subdivision must be coarser than the reference's `subdivide` (" +
                                 std::to_string(referenceSubdivide) + ")");
  auto data = std::make_shared<ElementsData>();
  for (const auto& h : c.step.highlights)
    if (!h.empty() && !std::isdigit(static_cast<unsigned char>(h[0]))) data->surfaces.push_back(h);
  data->referenceSubdivide = referenceSubdivide;
  data->referenceElements = static_cast<long>(r.mesh.size());

  // The reference: the linear basis on the step's own (finest) mesh. The views show it.
  c.progress.report(0.0, "reference (linear basis)");
  const auto reference = kernelFor(c, r.mesh);
  RgbField referenceNodal;
  runSolver(c, p.solver, linearSystem(*reference), referenceNodal, "reference");
  r.B = reference->basis.elementAverages(referenceNodal);
  r.corners = reference->basis.cornerValues(referenceNodal);
  const RadiosityField referenceField(r.mesh, reference->basis, referenceNodal);

  for (const std::string basis : {"constant", "linear"}) {
    BasisSeries series;
    series.basis = basis;
    std::vector<double> h, all;
    std::map<std::string, std::vector<double>> bySurface;
    for (const int n : subdivisions) {
      if (c.progress.cancelled()) throw Cancelled();
      MeshOptions o;
      o.mode = MeshOptions::Mode::Count;
      o.count = n;
      const Mesh mesh = buildMesh(r.scene, o);
      BasisErrorPoint point;
      point.subdivide = n;
      point.elements = static_cast<long>(mesh.size());
      RgbField B;
      std::unique_ptr<RadiosityField> field;
      std::shared_ptr<const LinearKernel> kernel;
      if (basis == "linear") {
        kernel = kernelFor(c, mesh);
        runSolver(c, p.solver, linearSystem(*kernel), B, "linear" + std::to_string(n));
        point.unknowns = static_cast<long>(kernel->basis.size());
        field = std::make_unique<RadiosityField>(mesh, kernel->basis, B);
      } else {
        FormFactorStats stats;
        const auto F = c.formFactors(mesh, c.method(), "subdivisions", stats);
        runSolver(c, p.solver, RadiositySystem::fromMesh(mesh, *F), B, "constant" + std::to_string(n));
        point.unknowns = point.elements;
        field = std::make_unique<RadiosityField>(mesh, B);
      }
      point.error = relativeL1Difference(*field, referenceField, 3);
      for (const auto& s : data->surfaces) {
        point.surfaceError[s] = relativeL1Difference(*field, referenceField, 3, surfacePatches(r.scene, s));
        bySurface[s].push_back(point.surfaceError[s]);
      }
      h.push_back(1.0 / n);
      all.push_back(point.error);
      const std::string index = "[" + std::to_string(series.points.size()) + "]";
      r.values["error." + basis + index] = point.error;
      r.values["unknowns." + basis + index] = static_cast<double>(point.unknowns);
      r.values["elements" + index] = static_cast<double>(point.elements);
      for (const auto& [s, e] : point.surfaceError) r.values["error." + basis + "." + s + index] = e;
      series.points.push_back(std::move(point));
    }
    series.order = logLogSlope(h, all);
    r.values["order." + basis] = series.order;
    for (const auto& [s, errors] : bySurface) {
      series.surfaceOrder[s] = logLogSlope(h, errors);
      r.values["order." + basis + "." + s] = series.surfaceOrder[s];
    }
    data->series.push_back(std::move(series));
  }
  r.values["elements.reference"] = static_cast<double>(r.mesh.size());
  r.values["nodes.reference"] = static_cast<double>(reference->basis.size());
  r.values["subdivide.reference"] = referenceSubdivide;
  // The highlighted surfaces name the regions measured, not elements to mark in the figure.
  r.highlighted.clear();
  r.elements = std::move(data);
}

}  // namespace rt::lesson::detail
