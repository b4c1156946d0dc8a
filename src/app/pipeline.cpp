#include "app/pipeline.h"

#include <sstream>
#include <stdexcept>

#include "core/mesh.h"
#include "core/solvers/radiosity_system.h"

namespace rt::app {
namespace {

std::string formFactorKey(const Mesh& mesh, const PipelineSettings& s) {
  std::ostringstream key;
  key << mesh.geometryHash() << '/' << s.method << '/' << s.formFactors.hemicubeResolution << '/'
      << s.formFactors.samples << '/' << s.formFactors.seed << '/' << s.formFactors.tolerance;
  return key.str();
}

}  // namespace

Scene applyOverrides(const Scene& scene, const PipelineSettings& settings) {
  Scene result = scene;
  for (const auto& [surfaceName, rho] : settings.reflectance) {
    auto it = std::find_if(result.surfaces.begin(), result.surfaces.end(),
                           [&](const Surface& s) { return s.name == surfaceName; });
    if (it == result.surfaces.end())
      throw InputError({scene.sourceFile},
                       "no surface named '" + surfaceName + "' to change the reflectance of");
    if ((rho < 0).any() || (rho >= 1).any())
      throw InputError({scene.sourceFile}, "reflectance of '" + surfaceName + "' must be in [0,1)");
    // The surface gets its own material so that others sharing the old one keep theirs.
    Material material = result.materials[it->material];
    material.name += "@" + surfaceName;
    material.reflectance = rho;
    result.materials.push_back(material);
    it->material = static_cast<int>(result.materials.size()) - 1;
  }
  if (settings.lightScale != 1.0) {
    if (!(settings.lightScale >= 0)) throw InputError({scene.sourceFile}, "the light scale must be >= 0");
    for (Material& m : result.materials) m.emission *= settings.lightScale;
  }
  return result;
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

void solveWithHistory(PipelineResult& result, const std::string& requestedSolver, SolverOptions options,
                      Progress& progress) {
  const Mesh& mesh = *result.mesh;
  result.solverName = requestedSolver.empty() ? chooseSolver(mesh.size()) : requestedSolver;
  std::unique_ptr<Solver> solver;
  try {
    solver = makeSolver(result.solverName);
  } catch (const std::invalid_argument& e) {
    result.note = std::string(e.what()) + ": showing direct light plus an ambient estimate";
    result.B = ambientEstimate(mesh);
    return;
  }
  options.recordHistory = true;
  solver->setOptions(options);
  solver->setProgress(&progress);
  const int cap = std::max(1, options.maxIterations);
  const std::string stage = "solve (" + result.solverName + ")";
  solver->setObserver([&](const IterationRecord& r) {
    progress.report(std::min(1.0, static_cast<double>(r.iteration) / cap), stage);
  });
  const RadiositySystem system = RadiositySystem::fromMesh(mesh, *result.F);
  progress.report(0.0, stage);
  result.B = solver->compute(system).solve();
  result.history = solver->history();
  result.status = solver->info();
  result.iterations = solver->iterations();
  result.residual = system.relativeResidual(result.B);
}

PipelineResult runPipeline(const Scene& input, const PipelineSettings& settings, Progress& progress,
                           const PipelineResult* previous) {
  PipelineResult result;
  auto scene = std::make_shared<Scene>(applyOverrides(input, settings));
  result.scene = scene;
  progress.report(0.0, "mesh");
  auto mesh = std::make_shared<Mesh>(buildMesh(*scene, settings.mesh));
  result.mesh = mesh;
  result.camera = scene->cameraOrDefault();
  result.title = scene->name;
  if (progress.cancelled()) throw Cancelled();

  result.formFactorKey = formFactorKey(*mesh, settings);
  if (previous && previous->F && previous->formFactorKey == result.formFactorKey) {
    result.F = previous->F;
    result.formFactorStats = previous->formFactorStats;
    result.formFactorsReused = true;
  } else {
    std::unique_ptr<FormFactorMethod> method;
    try {
      method = makeFormFactorMethod(settings.method);
    } catch (const std::invalid_argument& e) {
      result.note = std::string(e.what()) + ": showing direct light plus an ambient estimate";
    }
    if (method) {
      progress.report(0.0, "form factors (" + settings.method + ")");
      result.F = std::make_shared<FormFactorMatrix>(
          method->compute(*mesh, settings.formFactors, progress, result.formFactorStats));
    }
  }
  if (result.F) result.formFactorMethod = settings.method;
  if (!result.F) {
    result.B = ambientEstimate(*mesh);
    return result;
  }

  solveWithHistory(result, settings.solver, settings.solverOptions, progress);
  return result;
}

}  // namespace rt::app
