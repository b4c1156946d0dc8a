#include "core/pipeline/pipeline.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "core/io/scene_loader.h"
#include "core/pipeline/linear_solve.h"
#include "core/pipeline/scene_overrides.h"

namespace rt {

Pipeline::Pipeline(std::size_t cachedMatrices) : cache_(cachedMatrices) {}

std::shared_ptr<const CachedFormFactors> Pipeline::formFactors(const Mesh& mesh, const std::string& method,
                                                               const FormFactorOptions& options,
                                                               Progress& progress, bool* reused) {
  progress.report(0.0, "form factors (" + method + ")");
  return cache_.get(method, mesh, options, progress, reused);
}

bool Pipeline::holdsFormFactors(const Mesh& mesh, const std::string& method,
                                const FormFactorOptions& options) const {
  return cache_.holds(method, mesh, options);
}

void Pipeline::storeFormFactors(const Mesh& mesh, const std::string& method, const FormFactorOptions& options,
                                std::shared_ptr<const CachedFormFactors> value) {
  cache_.put(method, mesh, options, std::move(value));
}

MeshedScene meshScene(const Scene& input, const PipelineSettings& settings) {
  auto scene =
      std::make_shared<const Scene>(applyOverrides(input, settings.reflectance, settings.lightScale));
  auto mesh = std::make_shared<const Mesh>(buildMesh(*scene, settings.mesh));
  return {scene, mesh};
}

std::shared_ptr<const LinearKernel> Pipeline::linearKernel(const Mesh& mesh, const FormFactorOptions& options,
                                                           Progress& progress, bool* reused) {
  const std::uint64_t key = mesh.geometryHash();
  const bool same = linear_ && key == linearKey_ && options.tolerance == linearTolerance_;
  if (reused) *reused = same;
  if (same) return linear_;
  linear_ = computeLinearKernel(mesh, options, progress);
  linearKey_ = key;
  linearTolerance_ = options.tolerance;
  return linear_;
}

SolveOutcome solveRadiosity(const RadiositySystem& system, const std::string& requested,
                            SolverOptions options, bool recordHistory, Progress& progress,
                            const std::function<void(const IterationRecord&)>& observer) {
  SolveOutcome out;
  out.solverName = requested.empty() ? chooseSolver(system.size()) : requested;
  std::unique_ptr<Solver> solver = makeSolver(out.solverName);
  options.recordHistory = recordHistory;
  solver->setOptions(options);
  // The solver reports its own progress (by iterations and by residual, never backwards).
  solver->setProgress(&progress);
  solver->setObserver([&out, &observer](const IterationRecord& r) {
    out.trace.push_back({r.iteration, r.residual, r.seconds, r.shooter, r.rays, r.standardError,
                         r.emittedPower > 0 ? r.unshotPower / r.emittedPower : 0.0});
    out.standardError = r.standardError;
    out.rays = r.rays;
    out.links = r.links;
    out.nodes = r.nodes;
    out.memoryBytes = r.memoryBytes;
    if (observer) observer(r);
  });
  progress.report(0.0, "solve (" + out.solverName + ")");
  const auto start = std::chrono::steady_clock::now();
  solver->compute(system);
  out.B = solver->solve();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (recordHistory) out.history = solver->history();
  out.status = solver->info();
  out.iterations = solver->iterations();
  out.error = solver->error();
  out.standardErrors = solver->standardError();
  // Without F the exact residual cannot be computed; the solver's own measure stands in.
  out.residual = system.F ? system.relativeResidual(out.B) : out.error;
  return out;
}

RgbField ambientEstimate(const Mesh& mesh) {
  const Eigen::VectorXd areas = mesh.areas();
  const double total = areas.sum();
  RgbField B = mesh.emission;
  if (total <= 0) return B;
  for (int c = 0; c < 3; ++c) {
    const double emitted = mesh.emission.col(c).dot(areas) / total;
    const double rhoAverage = mesh.reflectance.col(c).dot(areas) / total;
    const double ambient = emitted / std::max(1e-6, 1.0 - rhoAverage);
    B.col(c) += mesh.reflectance.col(c) * ambient;
  }
  return B;
}

PipelineOutput Pipeline::run(const Scene& input, const PipelineSettings& settings, Progress& progress) {
  requireLight(input);
  PipelineOutput out;
  progress.report(0.0, "mesh");
  const MeshedScene meshed = meshScene(input, settings);
  out.scene = meshed.scene;
  out.mesh = meshed.mesh;
  const std::shared_ptr<const Mesh>& mesh = meshed.mesh;
  if (progress.cancelled()) throw Cancelled();
  if (settings.basis == Basis::Linear) {
    std::string problem;
    try {
      problem = linearBasisProblem(settings.solver, settings.method);
    } catch (const std::invalid_argument& e) {
      out.note = std::string(e.what()) + ": showing direct light plus an ambient estimate";
      out.solve.B = ambientEstimate(*mesh);
      return out;
    }
    if (!problem.empty()) throw InputError({}, problem);
    out.linear = linearKernel(*mesh, settings.formFactors, progress, &out.formFactorsReused);
    out.formFactorStats = out.linear->stats;
    out.formFactorMethod = settings.method;
    out.solve = solveLinearBasis(*out.linear, settings.solver, settings.solverOptions, settings.recordHistory,
                                 progress);
    return out;
  }
  const std::string solverName = settings.solver.empty() ? chooseSolver(mesh->size()) : settings.solver;
  bool needsMatrix = true;
  try {
    needsMatrix = solverNeedsMatrix(solverName);
  } catch (const std::invalid_argument& e) {
    out.note = std::string(e.what()) + ": showing direct light plus an ambient estimate";
    out.solve.B = ambientEstimate(*mesh);
    return out;
  }
  if (!needsMatrix) {
    // The solver traces its own rays through the mesh: no form factor is computed, nothing n x n is stored.
    out.solve = solveRadiosity(RadiositySystem::fromGeometry(*mesh), solverName, settings.solverOptions,
                               settings.recordHistory, progress);
    return out;
  }
  try {
    auto cached = formFactors(*mesh, settings.method, settings.formFactors, progress, &out.formFactorsReused);
    out.F = std::shared_ptr<const FormFactorMatrix>(cached, &cached->F);
    out.formFactorStats = cached->stats;
    out.formFactorMethod = settings.method;
  } catch (const std::invalid_argument& e) {
    out.note = std::string(e.what()) + ": showing direct light plus an ambient estimate";
    out.solve.B = ambientEstimate(*mesh);
    return out;
  }
  try {
    out.solve = solveRadiosity(RadiositySystem::fromMesh(*mesh, *out.F), settings.solver,
                               settings.solverOptions, settings.recordHistory, progress);
  } catch (const std::invalid_argument& e) {
    out.note = std::string(e.what()) + ": showing direct light plus an ambient estimate";
    out.solve.B = ambientEstimate(*mesh);
  }
  return out;
}

}  // namespace rt
