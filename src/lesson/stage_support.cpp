#include <chrono>

#include <algorithm>
#include <sstream>

#include "core/polygon.h"
#include "core/solvers/local_lines_solver.h"
#include "core/solvers/solver.h"
#include "lesson/lesson_parser.h"
#include "lesson/step_keys.h"
#include "lesson/step_settings.h"
#include "lesson/step_stages.h"

namespace rt::lesson::detail {

void addScenePatch(Scene& scene, const Polygon& polygon, int surface) {
  Patch p;
  p.vertices = polygon;
  p.normal = newellNormal(polygon).normalized();
  p.area = polygonArea(polygon);
  p.surface = surface;
  scene.patches.push_back(p);
}

SourceLocation StageContext::at(const std::string& key) const {
  auto it = step.fields.find(key);
  return {lesson.file, it == step.fields.end() ? step.line : it->second.line};
}

void StageContext::fail(const std::string& key, const std::string& message) const {
  throw InputError(at(key), "step '" + step.title + "': " + message);
}

void StageContext::failUnavailable(const std::string& key, const std::string& name,
                                   const std::string& what) const {
  const auto& known = knownMethods();
  if (std::find(known.begin(), known.end(), name) != known.end())
    throw MethodUnavailable(at(key), "step '" + step.title + "': form-factor method '" + name +
                                         "' is not included in this build");
  fail(key, what);
}

std::string StageContext::method() const {
  return methodOf(step);
}

FormFactorOptions StageContext::optionsFor(const std::string& name, int sweepValue) const {
  FormFactorOptions o = formFactorOptionsFor(parameters, name, sweepValue);
  if (runner.options().quick) {
    o.hemicubeResolution = std::min(o.hemicubeResolution, 32);
    o.samples = std::min(o.samples, 8);
  }
  return o;
}

std::string StageContext::replayedSolver() const {
  if (!parameters.solvers.empty() && !step.fields.count("solver")) return parameters.solvers.back();
  return parameters.solver;
}

std::shared_ptr<const FormFactorMatrix> StageContext::formFactors(const Mesh& mesh, const std::string& name,
                                                                  const std::string& fieldKey,
                                                                  FormFactorStats& stats) {
  try {
    return runner.formFactors(mesh, name, optionsFor(name, 0), stats, progress);
  } catch (const std::invalid_argument& e) {
    failUnavailable(fieldKey, name, e.what());
  }
}

SolverRun runSolver(StageContext& c, const std::string& name, const RadiositySystem& system, RgbField& B,
                    const std::string& label, bool replayable) {
  StepResult& r = c.result;
  const bool record = replayable && c.runner.options().recordHistory && name == c.replayedSolver() &&
                      r.replay.history.empty();
  SolveOutcome outcome;
  try {
    outcome = solveRadiosity(system, name, solverOptionsFor(c.parameters), record, c.progress);
  } catch (const std::invalid_argument& e) {
    c.fail(c.step.fields.count("solvers") ? "solvers" : "solver", e.what());
  }
  B = outcome.B;
  SolverRun run;
  run.label = label;
  for (const IterationPoint& rec : outcome.trace) {
    run.iteration.push_back(rec.iteration);
    run.residuals.push_back(rec.residual);
    run.elapsed.push_back(rec.seconds);
    if (rec.shooter >= 0) run.shooters.push_back(rec.shooter);
    if (rec.rays > 0) {
      run.rays.push_back(static_cast<double>(rec.rays));
      run.standardErrors.push_back(rec.standardError);
    }
  }
  run.seconds = outcome.seconds;
  run.iterations = outcome.iterations;
  run.residual = outcome.error;
  run.status = toString(outcome.status);
  const std::string suffix = label.empty() ? "" : "." + label;
  r.values["iterations" + suffix] = run.iterations;
  r.values["residual" + suffix] = run.residual;
  r.values["seconds" + suffix] = run.seconds;
  r.values["converged" + suffix] = outcome.status == SolverStatus::Success ? 1.0 : 0.0;
  const SolverOptions options = solverOptionsFor(c.parameters);
  r.values["tolerance"] = options.tolerance;
  if (name == "local-lines-regular")
    r.values["burn-in" + suffix] = regularBurnIn(system.reflectance.maxCoeff(), options.tolerance);
  if (outcome.rays > 0) {
    // Stochastic solvers: the rays, the noise, and what the first iteration already showed.
    if (options.raysPerIteration > 0)
      r.values["rays-per-iteration"] = static_cast<double>(options.raysPerIteration);
    else if (name.rfind("local-lines", 0) == 0)
      r.values["rays-per-iteration"] = static_cast<double>(localLinesDefaultRays(system.size()));
    r.values["rays" + suffix] = static_cast<double>(outcome.rays);
    r.values["standard-error" + suffix] = outcome.standardError;
    if (!outcome.trace.empty()) {
      r.values["rays.first" + suffix] = static_cast<double>(outcome.trace.front().rays);
      r.values["seconds.first" + suffix] = outcome.trace.front().seconds;
      r.values["unshot.first" + suffix] = outcome.trace.front().unshot;
    }
  }
  if (record) r.replay = std::move(outcome);
  return run;
}

void addSurfaceValues(StepResult& r, const std::string& prefix, const RgbField& field,
                      const std::string& suffix) {
  static const char* channels[] = {"r", "g", "b"};
  for (const auto& s : r.scene.surfaces) {
    const auto mean = surfaceMean(r.mesh, r.scene, field, s.name);
    if (!mean) continue;
    r.values[prefix + "." + s.name + suffix] = mean->mean();
    for (int ch = 0; ch < 3; ++ch)
      r.values[prefix + "." + s.name + "." + channels[ch] + suffix] = (*mean)[ch];
  }
}

void addShotValues(StepResult& r, const SolverRun& run) {
  if (run.shooters.empty()) return;
  for (const auto& s : r.scene.surfaces) {
    r.values["shots." + s.name] = 0;
    r.values["first-shot." + s.name] = 0;
  }
  for (std::size_t k = 0; k < run.shooters.size(); ++k) {
    const auto e = static_cast<std::size_t>(run.shooters[k]);
    if (e >= r.mesh.size()) continue;
    const std::string& name = r.scene.surfaces[r.scene.patches[r.mesh.elements[e].patch].surface].name;
    r.values["shots." + name] += 1;
    double& first = r.values["first-shot." + name];
    if (first == 0) first = static_cast<double>(k + 1);
  }
}

void addFormFactorValues(StepResult& r, const FormFactorMatrix& F, const std::string& suffix) {
  const Scene& scene = r.scene;
  const Mesh& mesh = r.mesh;
  const auto n = static_cast<Eigen::Index>(mesh.size());
  const Eigen::VectorXd areas = mesh.areas();
  const std::size_t surfaces = scene.surfaces.size();
  std::vector<int> surfaceOf(mesh.size());
  for (std::size_t e = 0; e < mesh.size(); ++e) surfaceOf[e] = scene.patches[mesh.elements[e].patch].surface;
  // Surface-to-surface: F_AB = (1/A_A) sum_{i in A} A_i sum_{j in B} F_ij.
  Eigen::MatrixXd transfer = Eigen::MatrixXd::Zero(surfaces, surfaces);
  Eigen::VectorXd surfaceArea = Eigen::VectorXd::Zero(surfaces);
  for (Eigen::Index i = 0; i < n; ++i) {
    surfaceArea[surfaceOf[i]] += areas[i];
    for (Eigen::Index j = 0; j < n; ++j) transfer(surfaceOf[i], surfaceOf[j]) += areas[i] * F(i, j);
  }
  for (std::size_t a = 0; a < surfaces; ++a) {
    if (surfaceArea[a] <= 0) continue;
    double sum = 0;
    for (std::size_t b = 0; b < surfaces; ++b) {
      const double f = transfer(a, b) / surfaceArea[a];
      r.values["F." + scene.surfaces[a].name + "." + scene.surfaces[b].name + suffix] = f;
      sum += f;
    }
    r.values["rowsum." + scene.surfaces[a].name + suffix] = sum;
  }
  const FormFactorDiagnostics d = diagnose(F, areas);
  r.values["rowsum.min" + suffix] = d.minRowSum;
  r.values["rowsum.max" + suffix] = d.maxRowSum;
  r.values["closure" + suffix] = d.maxClosureError;
  r.values["reciprocity" + suffix] = d.maxReciprocityError;
  r.values["negative" + suffix] = static_cast<double>(d.negativeEntries);
  if (suffix.empty()) {
    r.values["rays"] = static_cast<double>(r.formFactorStats.raysCast);
    r.values["seconds.formfactors"] = r.formFactorStats.seconds;
    r.values["standard-error"] = r.formFactorStats.standardError;
    r.values["pairs"] = static_cast<double>(r.formFactorStats.pairsComputed);
  }
}

std::string picturesKey(const StageContext& c, const std::vector<std::string>& ignored) {
  std::ostringstream key;
  key.precision(17);
  key << c.step.scene;
  for (const StepKey& k : stepKeyTable())
    if (k.name != "reflectance" && std::find(ignored.begin(), ignored.end(), k.name) == ignored.end())
      if (auto value = stepValueText(c.parameters, k, k.name)) key << '|' << k.name << '=' << *value;
  for (const auto& [surface, rho] : c.parameters.reflectance)
    key << "|rho." << surface << '=' << rho.transpose();
  const Camera& camera = c.result.camera;
  key << "|camera=" << camera.position.transpose() << ' ' << camera.target.transpose() << ' '
      << camera.up.transpose() << ' ' << camera.fovYDegrees;
  return key.str();
}

}  // namespace rt::lesson::detail
