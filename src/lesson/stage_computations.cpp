// The stages that go beyond "compute F": local illumination, the matrix, solving, comparing, bounces, the
// exact reference, benchmarks and refinement.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "core/assembly.h"
#include "core/io/matrix_export.h"
#include "core/refine/refine.h"
#include "core/solvers/energy.h"
#include "core/solvers/random_walks.h"
#include "core/solvers/solver.h"
#include "core/solvers/solver_support.h"
#include "lesson/step_settings.h"
#include "lesson/step_stages.h"

namespace rt::lesson::detail {
namespace {

std::shared_ptr<const FormFactorMatrix> mainFormFactors(StageContext& c) {
  StepResult& r = c.result;
  r.method = c.method();
  r.F = c.formFactors(r.mesh, r.method, "method", r.formFactorStats);
  return r.F;
}

// Luminance-like scalar of a row: the mean of the channels.
double level(const RgbField& B, Eigen::Index i) {
  return B.row(i).mean();
}

// Largest per-element difference relative to the brightest reflecting element of the reference.
double maxRelativeDifference(const Mesh& mesh, const RgbField& B, const RgbField& reference) {
  double scale = 0, worst = 0;
  for (Eigen::Index i = 0; i < reference.rows(); ++i)
    if (!(mesh.emission.row(i).array() > 0).any()) scale = std::max(scale, level(reference, i));
  for (Eigen::Index i = 0; i < reference.rows(); ++i)
    worst = std::max(worst, (B.row(i) - reference.row(i)).cwiseAbs().mean());  // as the error map shows it
  return scale > 0 ? worst / scale : worst;
}

double totalPower(const RgbField& X, const Eigen::VectorXd& areas) {
  return (X.array().colwise() * areas.array()).sum();
}

// The walks a walks view draws: how many of each solver's first walks.
constexpr long kDrawnWalks = 6;

// The first walks of the step's first discrete walk solver and of its photon-density solver, recorded with
// the step's solver options, so that they are the walks those solvers began with.
void recordDrawnWalks(StageContext& c, const RadiositySystem& withF, const RadiositySystem& traced) {
  StepResult& r = c.result;
  bool discrete = false;
  for (const std::string& s : c.parameters.solvers) {
    const bool photons = s == "photon-density";
    if (!photons && s != "random-walk" && s != "random-walk-absorption") continue;
    if (!photons && discrete) continue;  // the absorption estimator scores the same walks
    discrete = discrete || !photons;
    DrawnWalks drawn{s, {}};
    if (recordWalks(s, photons ? traced : withF, solverOptionsFor(c.parameters), kDrawnWalks, drawn.walks) !=
        SolverStatus::Success)
      c.fail("solvers", "the walks of " + s + " could not be recorded");
    double landings = 0, absorbed = 0, escaped = 0;
    for (const RecordedWalk& walk : drawn.walks) {
      landings += static_cast<double>(walk.landings.size());
      absorbed += walk.end == RecordedWalk::End::Absorbed ? 1 : 0;
      escaped += walk.end == RecordedWalk::End::Escaped ? 1 : 0;
    }
    r.values["drawn-landings." + s] = landings;
    r.values["drawn-absorbed." + s] = absorbed;
    r.values["drawn-escaped." + s] = escaped;
    r.walks.push_back(std::move(drawn));
  }
  if (r.walks.empty())
    c.fail("views",
           "the walks view draws the walks of random-walk, random-walk-absorption or photon-density; "
           "the step's solvers include none of them");
  r.values["drawn-walks"] = static_cast<double>(kDrawnWalks);
}

}  // namespace

Rgb classicAmbient(const Mesh& mesh, const RgbField& direct, double chosen) {
  // The light not yet accounted for (here: everything reflected once), spread evenly and amplified by the
  // mean interreflection factor 1 / (1 - mean rho).
  const Eigen::VectorXd areas = mesh.areas();
  const double totalArea = areas.sum();
  Rgb ambient;
  for (int ch = 0; ch < 3; ++ch) {
    const double rhoMean = mesh.reflectance.col(ch).dot(areas) / totalArea;
    const double unshot = direct.col(ch).dot(areas) / totalArea;
    ambient[ch] = chosen > 0 ? chosen : unshot / (1.0 - rhoMean);
  }
  return ambient;
}

void computeLocal(StageContext& c) {
  StepResult& r = c.result;
  const auto F = mainFormFactors(c);
  const Mesh& mesh = r.mesh;
  const Eigen::VectorXd areas = mesh.areas();
  // Direct light: what each element reflects of the emitters' light on its first bounce.
  const RgbField direct = (mesh.reflectance.array() * ((*F) * mesh.emission).array()).matrix();
  const Rgb ambient = classicAmbient(mesh, direct, c.parameters.ambientLight);
  r.local = mesh.emission + direct;
  for (Eigen::Index i = 0; i < r.local.rows(); ++i)
    r.local.row(i) += (mesh.reflectance.row(i).array() * ambient.transpose()).matrix();
  const RadiositySystem system = RadiositySystem::fromMesh(mesh, *F);
  r.runs.push_back(runSolver(c, "direct", system, r.B, "direct"));
  addSurfaceValues(r, "Blocal", r.local);
  addSurfaceValues(r, "Bdirect", RgbField(mesh.emission + direct));
  r.values["ambient"] = ambient.mean();
  r.values["local-error"] = maxRelativeDifference(mesh, r.local, r.B);
  // The two models over the whole room: area-weighted means of the elements that only reflect.
  double area = 0, local = 0, global = 0;
  for (Eigen::Index i = 0; i < r.B.rows(); ++i) {
    if ((mesh.emission.row(i).array() > 0).any()) continue;
    area += areas[i];
    local += areas[i] * level(r.local, i);
    global += areas[i] * level(r.B, i);
  }
  r.values["Blocal.mean"] = area > 0 ? local / area : 0;
  r.values["B.mean"] = area > 0 ? global / area : 0;
}

void computeMatrix(StageContext& c) {
  StepResult& r = c.result;
  const auto F = mainFormFactors(c);
  addFormFactorValues(r, *F);
  const Mesh& mesh = r.mesh;
  double radius = 0;
  static const char* channels[] = {"r", "g", "b"};
  for (int ch = 0; ch < 3; ++ch) {
    const SpectralRadiusEstimate s = spectralRadius(*F, mesh.reflectance.col(ch));
    r.values[std::string("spectral-radius.") + channels[ch]] = s.value;
    radius = std::max(radius, s.value);
  }
  r.values["spectral-radius"] = radius;
  // Sweeps of Jacobi per decade of error reduction: the error shrinks like radius^k.
  r.values["sweeps-per-decade"] = radius > 0 && radius < 1 ? -1.0 / std::log10(radius) : INFINITY;
  // Row i of K is diagonally dominant when 1 - rho_i F_ii > rho_i sum_{j != i} F_ij, i.e. rho_i sum_j F_ij
  // < 1.
  double margin = INFINITY;
  for (Eigen::Index i = 0; i < F->rows(); ++i)
    margin = std::min(margin, 1.0 - mesh.reflectance.row(i).maxCoeff() * F->row(i).sum());
  r.values["dominance"] = margin;
  r.values["rho.max"] = mesh.reflectance.maxCoeff();
  // m = max_i rho_i sum_j F_ij = ||rho F|| in the row-sum norm: it bounds the condition number,
  // (1 + m) / (1 - m), and a row-sum error e of F scales B by about 1 + e m / (1 - m) in a closed room.
  const double m = 1.0 - margin;
  if (m < 1.0) {
    r.values["condition.bound"] = (1.0 + m) / (1.0 - m);
    r.values["row-sum-gain"] = m / (1.0 - m);
  }
  r.values["fill"] = fillFraction(*F);
  const Eigen::MatrixXd K = assembleDense(*F, mesh.reflectance.col(1));
  if (K.rows() <= 300) {
    if (const auto cond = conditionNumber(K)) r.values["condition"] = *cond;
    if (const auto cond = infinityConditionNumber(K)) r.values["condition.inf"] = *cond;
  }
  r.values["K.diagonal.min"] = K.diagonal().minCoeff();
  r.values["K.diagonal.max"] = K.diagonal().maxCoeff();
  Eigen::MatrixXd offDiagonal = K.cwiseAbs();
  offDiagonal.diagonal().setZero();
  r.values["K.offdiagonal.max"] = offDiagonal.maxCoeff();
  const std::string& shown = c.parameters.matrix;
  r.shownMatrix = std::make_shared<const Eigen::MatrixXd>(
      shown == "K"      ? K
      : shown == "rhoF" ? Eigen::MatrixXd(Eigen::MatrixXd::Identity(K.rows(), K.cols()) - K)
                        : Eigen::MatrixXd(*F));
  // The solution beside the matrix: the 3D view shows it and a reader can replay the solver.
  r.runs.push_back(
      runSolver(c, c.parameters.solver, RadiositySystem::fromMesh(mesh, *F), r.B, c.parameters.solver, true));
  if (!c.parameters.exportMatrix.empty() && !c.runner.options().outputDir.empty()) {
    const std::string path =
        (std::filesystem::path(c.runner.options().outputDir) / c.parameters.exportMatrix).string();
    std::filesystem::create_directories(c.runner.options().outputDir);
    const bool exportF = c.parameters.exportMatrix[0] == 'F';
    const FormFactorMatrix M = exportF ? *F : FormFactorMatrix(K);
    writeMatrix(M, path);
    r.exportedMatrix = path;
  }
}

void computeSolve(StageContext& c) {
  StepResult& r = c.result;
  if (c.parameters.basis == "linear") return computeSolveLinear(c);
  if (!solverNeedsMatrix(c.parameters.solver)) {
    // A solver that traces its own rays: no form factor is computed, the result holds no F.
    const RadiositySystem system = RadiositySystem::fromGeometry(r.mesh);
    r.runs.push_back(runSolver(c, c.parameters.solver, system, r.B, c.parameters.solver, true));
    for (const char* key : {"iterations", "residual", "seconds", "converged", "rays", "standard-error",
                            "rays.first", "seconds.first", "unshot.first", "burn-in"})
      if (const auto it = r.values.find(std::string(key) + "." + c.parameters.solver); it != r.values.end())
        r.values[key] = it->second;
    return;
  }
  const auto F = mainFormFactors(c);
  addFormFactorValues(r, *F);
  const RadiositySystem system = RadiositySystem::fromMesh(r.mesh, *F);
  r.runs.push_back(runSolver(c, c.parameters.solver, system, r.B, c.parameters.solver, true));
  addShotValues(r, r.runs.back());
  for (const char* key : {"iterations", "residual", "seconds", "converged"})
    r.values[key] = r.values[std::string(key) + "." + c.parameters.solver];
  const Rgb emitted = emittedPower(system), absorbed = absorbedPower(system, r.B),
            escaped = escapedPower(system, r.B);
  r.values["power.emitted"] = emitted.sum();
  r.values["power.absorbed"] = absorbed.sum();
  r.values["power.escaped"] = escaped.sum();
  // The two sides of B = E + rho H for each surface: the irradiance H = F B it receives, and the radiance
  // L = B / pi it sends into every direction (diffuse surfaces).
  addSurfaceValues(r, "H", RgbField(*F * r.B));
  addSurfaceValues(r, "L", RgbField(r.B / 3.14159265358979323846));
}

void computeCompare(StageContext& c) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  if (!p.solvers.empty()) {
    // F only when a listed solver reads it; the solvers that trace rays get the geometry alone either way.
    const bool matrix = std::any_of(p.solvers.begin(), p.solvers.end(), solverNeedsMatrix);
    const auto F = matrix ? mainFormFactors(c) : nullptr;
    const RadiositySystem traced = RadiositySystem::fromGeometry(r.mesh);
    const RadiositySystem withF = F ? RadiositySystem::fromMesh(r.mesh, *F) : traced;
    if (F) {
      const double n = static_cast<double>(r.mesh.size());
      r.values["bytes.F"] = 8.0 * n * n;  // dense, in doubles
      r.values["seconds.formfactors"] = r.formFactorStats.seconds;
    }
    // The first solver is the reference the others are measured against (the error view shows the last one).
    for (const auto& s : p.solvers) {
      RgbField B;
      r.runs.push_back(runSolver(c, s, solverNeedsMatrix(s) ? withF : traced, B, s, true));
      addSurfaceValues(r, "B", B, "." + s);
      if (r.reference.rows() == 0) {
        r.reference = B;
      } else {
        r.values["difference." + s] = maxRelativeDifference(r.mesh, B, r.reference);
        // The measure the stochastic solvers' standard error is given in, so that the two can be compared.
        r.values["rms-error." + s] =
            solver_detail::relativeAreaRms(B - r.reference, r.reference, r.mesh.areas());
      }
      r.B = B;
    }
    if (std::find(c.step.views.begin(), c.step.views.end(), View::Walks) != c.step.views.end())
      recordDrawnWalks(c, withF, traced);
    if (r.runs.size() >= 2 && r.runs[1].iterations > 0)
      r.values["speedup"] = static_cast<double>(r.runs[0].iterations) / r.runs[1].iterations;
  }
  for (const auto& m : p.methods) {
    FormFactorStats stats;
    const auto F = c.formFactors(r.mesh, m, "methods", stats);
    const RadiositySystem system = RadiositySystem::fromMesh(r.mesh, *F);
    RgbField B;
    runSolver(c, p.solver, system, B, m, !r.F);
    addFormFactorValues(r, *F, "." + m);
    addSurfaceValues(r, "B", B, "." + m);
    r.values["seconds.formfactors." + m] = stats.seconds;
    r.values["rays." + m] = static_cast<double>(stats.raysCast);
    if (!r.variants.empty())
      r.values["difference." + m] = maxRelativeDifference(r.mesh, B, r.variants.front().B);
    r.variants.push_back({m, r.mesh, B});
    if (!r.F) {
      r.F = F;
      r.method = m;
      r.B = B;
    }
  }
  for (int n : p.subdivisions) {
    MeshOptions o;
    o.mode = MeshOptions::Mode::Count;
    o.count = n;
    Mesh mesh = buildMesh(r.scene, o);
    FormFactorStats stats;
    const auto F = c.formFactors(mesh, c.method(), "subdivisions", stats);
    const RadiositySystem system = RadiositySystem::fromMesh(mesh, *F);
    RgbField B;
    const std::string label = "sub" + std::to_string(n);
    r.runs.push_back(runSolver(c, p.solver, system, B, label));
    r.values["elements." + label] = static_cast<double>(mesh.size());
    StepResult view;  // surface means on this variant's mesh
    view.scene = r.scene;
    view.mesh = mesh;
    addSurfaceValues(view, "B", B, "." + label);
    r.values.insert(view.values.begin(), view.values.end());
    r.variants.push_back({label, std::move(mesh), B});
  }
  if (r.B.rows() == 0 && !r.variants.empty()) {
    r.mesh = r.variants.back().mesh;
    r.B = r.variants.back().B;
    r.highlighted.clear();
    r.sourceElement = 0;
  }
}

void computeBounces(StageContext& c) {
  StepResult& r = c.result;
  const auto F = mainFormFactors(c);
  const Mesh& mesh = r.mesh;
  const Eigen::VectorXd areas = mesh.areas();
  const RadiositySystem system = RadiositySystem::fromMesh(mesh, *F);
  RgbField exact;
  runSolver(c, "direct", system, exact, "direct");
  r.reference = exact;
  const double exactPower = totalPower(exact, areas);
  const double emitted = totalPower(mesh.emission, areas);
  RgbField term = mesh.emission, sum = mesh.emission;
  SolverRun run;
  run.label = "bounces";
  for (int k = 0; k <= c.parameters.bounces; ++k) {
    if (k > 0) {
      term = (mesh.reflectance.array() * ((*F) * term).array()).matrix();
      sum += term;
    }
    r.bounceTerms.push_back(term);
    const std::string index = "[" + std::to_string(k) + "]";
    r.values["bounce" + index] = emitted > 0 ? totalPower(term, areas) / emitted : 0;
    r.values["fraction" + index] = exactPower > 0 ? totalPower(sum, areas) / exactPower : 0;
    addSurfaceValues(r, "B", sum, ".bounce" + index);
    run.iteration.push_back(k);
    run.residuals.push_back(system.relativeResidual(sum));
    run.elapsed.push_back(0);
  }
  run.iterations = c.parameters.bounces;
  // Counted as the app counts them: bounce 0 is the emission, so B after this many bounces is the sum.
  r.values["iterations.bounces"] = run.iterations;
  run.residual = run.residuals.back();
  r.runs.push_back(run);
  r.B = sum;
  addSurfaceValues(r, "Bexact", exact);
  r.values["amplification"] = emitted > 0 ? exactPower / emitted : 0;
}

void computeExact(StageContext& c) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  FormFactorStats referenceStats;
  r.referenceF = c.formFactors(r.mesh, p.reference, "reference", referenceStats);
  const FormFactorMatrix& Fref = *r.referenceF;
  addFormFactorValues(r, Fref, ".reference");
  RgbField Bref;
  runSolver(c, "direct", RadiositySystem::fromMesh(r.mesh, Fref), Bref, "reference");
  r.reference = Bref;
  const std::vector<std::string> methods =
      p.methods.empty() ? std::vector<std::string>{c.method()} : p.methods;
  for (const auto& m : methods) {
    FormFactorStats stats;
    const auto F = c.formFactors(r.mesh, m, p.methods.empty() ? "method" : "methods", stats);
    const FormFactorMatrix diff = *F - Fref;
    r.values["error." + m] = diff.cwiseAbs().maxCoeff();
    r.values["rms." + m] = std::sqrt(diff.squaredNorm() / static_cast<double>(diff.size()));
    r.values["relative." + m] = Fref.norm() > 0 ? diff.norm() / Fref.norm() : diff.norm();
    r.values["seconds.formfactors." + m] = stats.seconds;
    addFormFactorValues(r, *F, "." + m);
    RgbField B;
    runSolver(c, "direct", RadiositySystem::fromMesh(r.mesh, *F), B, m);
    r.values["B-error." + m] = maxRelativeDifference(r.mesh, B, Bref);
    if (!r.F) {
      r.F = F;
      r.method = m;
      r.formFactorStats = stats;
      r.B = B;
      addFormFactorValues(r, *F);
    }
  }
}

void computeBenchmark(StageContext& c) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  FormFactorStats referenceStats;
  r.referenceF = c.formFactors(r.mesh, p.reference, "reference", referenceStats);
  const double referenceNorm = r.referenceF->norm();
  for (const auto& m : p.methods) {
    for (std::size_t k = 0; k < p.sweep.size(); ++k) {
      FormFactorStats stats;
      const auto start = std::chrono::steady_clock::now();
      std::shared_ptr<const FormFactorMatrix> F;
      try {
        F = c.runner.formFactors(r.mesh, m, c.optionsFor(m, p.sweep[k]), stats, c.progress);
      } catch (const std::invalid_argument& e) {
        c.failUnavailable("methods", m, e.what());
      }
      const double measured = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      BenchmarkPoint point{m, p.sweep[k], stats.seconds > 0 ? stats.seconds : measured, 0};
      point.error = (*F - *r.referenceF).norm() / (referenceNorm > 0 ? referenceNorm : 1.0);
      r.benchmark.push_back(point);
      const std::string index = "[" + std::to_string(k) + "]";
      r.values["error." + m + index] = point.error;
      r.values["seconds." + m + index] = point.seconds;
      r.values["parameter." + m + index] = point.parameter;
    }
  }
  r.F = r.referenceF;
  r.method = p.reference;
}

void computeRefine(StageContext& c) {
  StepResult& r = c.result;
  const StepParameters& p = c.parameters;
  RefineOptions o;
  o.mode = refineModeFromString(p.refine);
  if (p.refineTolerance) {
    o.gradientTolerance = *p.refineTolerance;
    o.linkTolerance = *p.refineTolerance;
  }
  if (p.maxEdge) o.initialMaxEdge = *p.maxEdge;
  if (p.samples) o.visibilitySamples = *p.samples;
  if (c.runner.options().quick) {
    o.maxElements = 400;
    o.maxPasses = 2;
    o.refinementRounds = 1;
    o.visibilitySamples = std::min(o.visibilitySamples, 4);
  }
  const RefinedSolution solution = solveRefined(r.scene, o, c.progress);
  r.mesh = solution.mesh;
  r.B = solution.B;
  r.highlighted.clear();
  r.sourceElement = 0;
  r.values["elements"] = static_cast<double>(solution.mesh.size());
  r.values["elements.initial"] = static_cast<double>(solution.stats.initialElements);
  r.values["links"] = static_cast<double>(solution.stats.links);
  r.values["levels"] = solution.stats.maxLevel;
  r.values["passes"] = static_cast<double>(solution.stats.passes.size());
  r.values["pairs"] = static_cast<double>(solution.stats.pairsComputed);
  r.values["t-vertices"] = static_cast<double>(solution.stats.tVertices);
  r.values["critical-segments"] = static_cast<double>(solution.stats.criticalSegments);
  r.values["seconds"] = solution.stats.seconds;
  r.values["refine-tolerance"] = o.mode == RefineMode::Hierarchical ? o.linkTolerance : o.gradientTolerance;
  // The critical lines by kind: umbra or outer penumbra boundaries (the light wholly on one side of the
  // critical plane) against lines inside a penumbra; vertex of the light with an occluder edge (VE) against
  // light edge with an occluder vertex (EV).
  double extremal = 0, ve = 0;
  for (const CriticalSegment& s : solution.discontinuities) {
    extremal += s.extremal ? 1 : 0;
    ve += s.kind == CriticalSegment::Kind::VE ? 1 : 0;
  }
  const double segments = static_cast<double>(solution.discontinuities.size());
  r.values["critical-segments.extremal"] = extremal;
  r.values["critical-segments.interior"] = segments - extremal;
  r.values["critical-segments.ve"] = ve;
  r.values["critical-segments.ev"] = segments - ve;
  // The adaptive split threshold at the final solution.
  r.values["luminance.mean"] = meanReflectingLuminance(solution.mesh, solution.B);
  r.values["split-threshold"] = o.gradientTolerance * r.values["luminance.mean"];
  r.refined = std::make_shared<const RefinedSolution>(solution);
}

}  // namespace rt::lesson::detail
