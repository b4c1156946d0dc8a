// radiosity figure: every view of the visualisation layer, headless, as PNG (all views), SVG/PDF (true
// vectors for the 2D views; 3D views embed a high-resolution raster). The command computes what the view
// needs through core.
#include <algorithm>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/setting_options.h"
#include "core/formfactor/analytic.h"
#include "core/formfactor/formfactor_method.h"
#include "core/formfactor/hemicube.h"
#include "core/refine/refine.h"
#include "core/solvers/solver.h"
#ifdef RT_HAVE_VIZ
#include "viz/chart.h"
#include "viz/exact_visibility.h"
#include "viz/hemicube_view.h"
#include "viz/matrix_view.h"
#include "viz/meshing_view.h"
#include "viz/nusselt_view.h"
#include "viz/rays_view.h"
#include "viz/scene_view.h"
#include "viz/timing_table.h"
#include "viz/visibility_view.h"
#endif

namespace rt::cli {
namespace {

struct FigureArguments {
  std::string scene, view = "scene", output;
  int width = 1200, height = 900;
  double dpi = 96;
  MeshArguments mesh;
  std::string formFactors = defaultFormFactorMethod(), referenceFormFactors, solver;
  int resolution = 128, samples = 16, maxIterations = 0;
  // scene view
  std::string colour = "radiosity", toneMap = "linear", colourMap = "viridis", errorMeasure = "relative";
  double exposure = 0;
  bool smooth = false, edges = false, noGamma = false, logScale = false, noColourBar = false;
  // element choice and the other views
  int element = -1, target = -1, row = -1, column = -1;
  std::string channel = "g";
  std::string matrix = "F", part = "auto", xAxis = "iteration";
  std::vector<std::string> solvers;
  std::string input;  // runtime-error: a timing table measured earlier
  // Meshes that follow the light: scene (--mesh), links (hierarchical), discontinuity.
  std::string refineMode, linkColour = "level";
  RefineOptions refine;
};

#ifdef RT_HAVE_VIZ
struct Computed {
  Scene scene;
  Mesh mesh;
};

FormFactorMatrix formFactors(const Mesh& mesh, const std::string& name, const FigureArguments& a) {
  FormFactorOptions options;
  options.hemicubeResolution = a.resolution;
  options.samples = a.samples;
  ProgressLine progress;
  FormFactorStats stats;
  FormFactorMatrix F = makeFormFactorMethod(name)->compute(mesh, options, progress, stats);
  progress.finish();
  std::cerr << "form factors (" << name << "): " << stats.summary() << "\n";
  return F;
}

std::unique_ptr<Solver> runSolver(const std::string& name, const RadiositySystem& system, int maxIterations,
                                  double tolerance, RgbField& B) {
  auto solver = makeSolver(name);
  SolverOptions options;
  options.tolerance = tolerance;
  if (maxIterations > 0) options.maxIterations = maxIterations;
  options.recordHistory = true;
  solver->setOptions(options);
  B = solver->compute(system).solve();
  if (solver->info() != SolverStatus::Success && solver->info() != SolverStatus::NoConvergence)
    throw std::runtime_error("solver " + name + " failed: " + toString(solver->info()));
  return solver;
}

int firstEmitter(const Mesh& mesh) {
  for (std::size_t e = 0; e < mesh.size(); ++e)
    if (mesh.emission.row(static_cast<Eigen::Index>(e)).maxCoeff() > 0) return static_cast<int>(e);
  return 0;
}

// The element that sees `target` best (largest point-to-polygon form factor from its centroid): a readable
// default.
int bestViewer(const Mesh& mesh, int target) {
  int best = target == 0 && mesh.size() > 1 ? 1 : 0;
  double bestF = -1;
  const Polygon receiver = mesh.polygon(target);
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    if (static_cast<int>(e) == target) continue;
    const double f = pointToPolygonFormFactor(mesh.elements[e].centroid, mesh.elements[e].normal, receiver);
    if (f > bestF) {
      bestF = f;
      best = static_cast<int>(e);
    }
  }
  return best;
}

void checkElement(int e, const Mesh& mesh, const char* option) {
  if (e < -1 || e >= static_cast<int>(mesh.size()))
    throw std::invalid_argument(std::string(option) + " " + std::to_string(e) + " is outside 0.." +
                                std::to_string(mesh.size() - 1));
}

viz::SceneViewOptions sceneOptions(const FigureArguments& a) {
  viz::SceneViewOptions o;
  o.image.width = a.width;
  o.image.height = a.height;
  o.image.exposure = a.exposure;
  o.image.toneMap = viz::toneMapFromName(a.toneMap);
  o.image.srgbGamma = !a.noGamma;
  o.image.smooth = a.smooth;
  o.image.showEdges = a.edges;
  o.legend.map = viz::colourMapFromName(a.colourMap);
  o.legend.logScale = a.logScale;
  o.colourBar = !a.noColourBar;
  o.dpi = a.dpi;
  return o;
}

RefinedSolution refined(const Computed& c, const FigureArguments& a, RefineMode mode) {
  RefineOptions options = a.refine;
  options.mode = mode;
  ProgressLine progress;
  RefinedSolution solution = solveRefined(c.scene, options, progress);
  progress.finish();
  std::cerr << "mesh: " << solution.stats.summary() << "\n";
  return solution;
}

void sceneFigure(const Computed& c, const FigureArguments& a, CLI::App& command) {
  viz::SceneViewOptions o = sceneOptions(a);
  o.colouring = viz::sceneColouringFromName(a.colour);
  o.errorMeasure = viz::errorMeasureFromName(a.errorMeasure);
  viz::SceneViewData data;
  if (!a.refineMode.empty()) {
    // The mesh a refining solver made, with its own radiosity (form factors and solver are its own).
    if (o.colouring == viz::SceneColouring::Error || o.colouring == viz::SceneColouring::UnshotPower)
      throw std::invalid_argument("--mesh shows radiosity, reflectance, emission or element colours");
    const RefinedSolution s = refined(c, a, refineModeFromString(a.refineMode));
    data.B = s.B;
    if (o.caption.empty()) o.caption = a.refineMode + " mesh: " + std::to_string(s.mesh.size()) + " elements";
    viz::writeSceneFigure(s.mesh, c.scene.cameraOrDefault(), data, o, a.output);
    return;
  }
  const bool needsB = o.colouring == viz::SceneColouring::Radiosity ||
                      o.colouring == viz::SceneColouring::Error ||
                      o.colouring == viz::SceneColouring::UnshotPower;
  if (needsB) {
    const FormFactorMatrix F = formFactors(c.mesh, a.formFactors, a);
    const RadiositySystem system = RadiositySystem::fromMesh(c.mesh, F);
    if (o.colouring == viz::SceneColouring::UnshotPower) {
      // Unshot power after a few shots of progressive refinement.
      const int shots = a.maxIterations > 0 ? a.maxIterations : 8;
      auto solver = runSolver("progressive", system, shots, 1e-12, data.B);
      data.unshot = solver->history().back().unshot;
      o.caption = "unshot power after " + std::to_string(solver->iterations()) + " shots";
    } else if (o.colouring == viz::SceneColouring::Error) {
      // Against the direct solution with the reference form factors: defaults show the error of 3 Jacobi
      // sweeps.
      const bool defaults = command.count("--solver") == 0 && command.count("--iterations") == 0 &&
                            command.count("--reference-formfactors") == 0;
      const std::string solver =
          defaults ? "jacobi" : (a.solver.empty() ? chooseSolver(c.mesh.size()) : a.solver);
      const int iterations = defaults ? 3 : a.maxIterations;
      runSolver(solver, system, iterations, 1e-12, data.B);
      const std::string refName = a.referenceFormFactors.empty() ? a.formFactors : a.referenceFormFactors;
      const FormFactorMatrix Fref = refName == a.formFactors ? F : formFactors(c.mesh, refName, a);
      const RadiositySystem refSystem = RadiositySystem::fromMesh(c.mesh, Fref);
      runSolver("direct", refSystem, 0, 1e-12, data.reference);
      o.caption = std::string(o.errorMeasure == viz::ErrorMeasure::Relative      ? "relative "
                              : o.errorMeasure == viz::ErrorMeasure::OfBrightest ? "brightest-relative "
                                                                                 : "") +
                  "error: " + solver +
                  (iterations > 0 ? ", " + std::to_string(iterations) + " iterations" : "") +
                  (refName == a.formFactors ? "" : ", " + a.formFactors + " F") + " vs direct" +
                  (refName == a.formFactors ? "" : ", " + refName + " F");
    } else {
      runSolver(a.solver.empty() ? chooseSolver(c.mesh.size()) : a.solver, system, a.maxIterations, 1e-8,
                data.B);
    }
  }
  viz::writeSceneFigure(c.mesh, c.scene.cameraOrDefault(), data, o, a.output);
}

void formFactorFigure(const Computed& c, const FigureArguments& a) {
  const int i = a.element >= 0 ? a.element : firstEmitter(c.mesh);
  const FormFactorMatrix F = formFactors(c.mesh, a.formFactors, a);
  viz::SceneViewOptions o = sceneOptions(a);
  o.colouring = viz::SceneColouring::Scalar;
  o.highlightElement = i;
  viz::SceneViewData data;
  data.scalar = F.row(i).transpose();
  o.legend.title = "F_" + std::to_string(i) + ",j";
  o.caption = "form factors from element " + std::to_string(i) + " (" + a.formFactors + ")";
  if (!a.referenceFormFactors.empty()) {
    const FormFactorMatrix Fref = formFactors(c.mesh, a.referenceFormFactors, a);
    data.scalar = (F.row(i) - Fref.row(i)).cwiseAbs().transpose();
    o.legend.title = "|F - F_ref|";  // short: the colour bar is narrow
    o.caption =
        "|F_" + std::to_string(i) + "j| difference: " + a.formFactors + " against " + a.referenceFormFactors;
  }
  viz::writeSceneFigure(c.mesh, c.scene.cameraOrDefault(), data, o, a.output);
}

void matrixFigure(const Computed& c, const FigureArguments& a) {
  const FormFactorMatrix F = formFactors(c.mesh, a.formFactors, a);
  viz::MatrixViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  o.logScale = a.logScale || a.matrix == "F";
  o.map = viz::colourMapFromName(a.colourMap);
  o.selectedRow = a.row;
  o.selectedColumn = a.column;
  for (const Element& e : c.mesh.elements) o.groups.push_back(e.patch);
  Eigen::MatrixXd shown = F;
  if (!a.referenceFormFactors.empty()) {
    shown = F - formFactors(c.mesh, a.referenceFormFactors, a);
    o.title = "F (" + a.formFactors + ") - F (" + a.referenceFormFactors + ")";
    o.valueLabel = "dF_ij";
  } else if (a.matrix == "K") {
    const int channel = channelIndex(a.channel);
    shown = Eigen::MatrixXd::Identity(F.rows(), F.cols()) -
            c.mesh.reflectance.col(channel).asDiagonal() * Eigen::MatrixXd(F);
    o.title = std::string("System matrix K = I - diag(rho) F (") + "RGB"[channel] + ")";
    o.valueLabel = "K_ij";
  } else {
    o.title = "Form factors F_ij (" + a.formFactors + ")";
  }
  viz::writeMatrixFigure(shown, o, a.output);
}

void nusseltFigure(const Computed& c, const FigureArguments& a) {
  const int j = a.target >= 0 ? a.target : firstEmitter(c.mesh);
  const int i = a.element >= 0 ? a.element : bestViewer(c.mesh, j);
  const Element& from = c.mesh.elements[i];
  const viz::NusseltConstruction construction =
      viz::nusseltConstruction(from.centroid, from.normal, c.mesh.polygon(j), 96);
  viz::NusseltViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  o.title = "Nusselt analog: centre of element " + std::to_string(i) + " to element " + std::to_string(j);
  std::cerr << "nusselt: projected area / pi = " << construction.diskAreaFraction
            << ", exact = " << construction.exact << "\n";
  std::string part = a.part;
  if (part == "auto") part = viz::figureFormatOf(a.output) == viz::FigureFormat::Png ? "hemisphere" : "disk";
  if (part == "disk")
    viz::writeNusseltDiskFigure(construction, o, a.output);
  else if (part == "hemisphere" || part == "3d")
    viz::writeNusseltHemisphereFigure(construction, o, a.output);
  else
    throw std::invalid_argument("--part for the nusselt view is disk or hemisphere, not '" + part + "'");
}

void hemicubeFigure(const Computed& c, const FigureArguments& a, CLI::App& command) {
  const int i = a.element >= 0 ? a.element : bestViewer(c.mesh, firstEmitter(c.mesh));
  // A teaching resolution by default: pixels large enough to see.
  const int resolution = command.count("--resolution") > 0 ? a.resolution : 16;
  const HemicubeFaces faces = renderHemicube(c.mesh, i, resolution);
  viz::HemicubeViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  o.colouring =
      a.colour == "delta" ? viz::HemicubeColouring::DeltaFormFactors : viz::HemicubeColouring::ItemBuffer;
  if (a.colour != "delta" && a.colour != "items" && command.count("--colour") > 0)
    throw std::invalid_argument("--colour for the hemicube view is items or delta, not '" + a.colour + "'");
  o.map = viz::colourMapFromName(a.colourMap);
  if (a.part == "3d" || a.part == "hemisphere")
    viz::writeHemicube3dFigure(c.mesh, faces, o, a.output);
  else if (a.part == "auto" || a.part == "faces")
    viz::writeHemicubeFacesFigure(faces, c.mesh.size(), o, a.output);
  else
    throw std::invalid_argument("--part for the hemicube view is faces or 3d, not '" + a.part + "'");
}

void raysFigure(const Computed& c, const FigureArguments& a, CLI::App& command) {
  const int j = a.target >= 0 ? a.target : firstEmitter(c.mesh);
  int i = a.element;
  if (i < 0) {
    // The default shows occlusion when there is some: among the elements that face j, the one whose view of j
    // is closest to half blocked (a quick 16-ray estimate on the 64 best-placed candidates).
    std::vector<std::pair<double, int>> candidates;
    const Polygon target = c.mesh.polygon(j);
    for (std::size_t e = 0; e < c.mesh.size(); ++e)
      if (static_cast<int>(e) != j)
        if (const double f =
                pointToPolygonFormFactor(c.mesh.elements[e].centroid, c.mesh.elements[e].normal, target);
            f > 0)
          candidates.emplace_back(f, static_cast<int>(e));
    std::sort(candidates.rbegin(), candidates.rend());
    if (candidates.size() > 64) candidates.resize(64);
    double best = 2;
    i = candidates.empty() ? (j == 0 ? 1 : 0) : candidates.front().second;
    for (const auto& [f, e] : candidates) {
      const double blocked = std::abs(viz::sampleRays(c.mesh, e, j, 16).visibleFraction() - 0.5);
      if (blocked < best) {
        best = blocked;
        i = e;
      }
    }
  }
  const int samples = command.count("--samples") > 0 ? a.samples : 64;
  const viz::RaySample sample = viz::sampleRays(c.mesh, i, j, samples);
  std::cerr << "rays: " << sample.visibleFraction() * 100 << "% of " << samples << " unoccluded from " << i
            << " to " << j << "\n";
  viz::RaysViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  viz::writeRaysFigure(c.mesh, c.scene.cameraOrDefault(), sample, o, a.output);
}

void visibilityFigure(const Computed& c, const FigureArguments& a) {
  // Default: the element that sees the emitter closest to half blocked is the telling one.
  const int j = a.target >= 0 ? a.target : firstEmitter(c.mesh);
  const int i = a.element >= 0 ? a.element : viz::halfBlockedViewer(c.mesh, j, bestViewer(c.mesh, j));
  const viz::VisibilityRegions regions = viz::exactVisibilityRegions(c.mesh, i, j);
  viz::VisibilityViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  std::cerr << "visibility: F = " << regions.formFactor << " of " << regions.unoccludedFormFactor
            << " unoccluded\n";
  viz::writeVisibilityFigure(regions, o, a.output);
}

void linksFigure(const Computed& c, const FigureArguments& a) {
  const RefinedSolution s = refined(c, a, RefineMode::Hierarchical);
  viz::LinksViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  o.colouring = viz::linkColouringFromName(a.linkColour);
  o.map = viz::colourMapFromName(a.colourMap);
  if (a.element >= static_cast<int>(s.mesh.size()))
    throw std::invalid_argument("--element " + std::to_string(a.element) + " is outside the " +
                                std::to_string(s.mesh.size()) + " leaves of the hierarchy");
  o.element = a.element;
  viz::writeLinksFigure(s, c.scene.cameraOrDefault(), o, a.output);
}

void discontinuityFigure(const Computed& c, const FigureArguments& a) {
  const RefinedSolution s = refined(c, a, RefineMode::Discontinuity);
  viz::DiscontinuityViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  o.image = sceneOptions(a).image;
  const viz::CriticalLineCounts counts = viz::countCriticalLines(s);
  std::cerr << "discontinuity: " << counts.extremal << " umbra/penumbra boundaries, " << counts.interior
            << " lines inside penumbrae\n";
  viz::writeDiscontinuityFigure(s, c.scene.cameraOrDefault(), o, a.output);
}

// Run time against error from a table measured earlier (bench formfactors or bench solvers CSV).
void timingTableFigure(const FigureArguments& a) {
  const viz::TimingTable table = viz::readTimingTable(a.input);
  viz::ChartOptions o;
  o.width = a.width;
  o.height = a.height;
  o.dpi = a.dpi;
  o.logX = o.logY = true;
  o.title = "Run time against error";
  o.xLabel = "time (s)";
  o.yLabel = table.errorColumn == "rms_error" ? "RMS error of F" : table.errorColumn;
  viz::writeLineChart(table.series, o, a.output);
}

void chartFigure(const Computed& c, const FigureArguments& a) {
  const FormFactorMatrix F = formFactors(c.mesh, a.formFactors, a);
  const RadiositySystem system = RadiositySystem::fromMesh(c.mesh, F);
  viz::ChartOptions o;
  o.width = a.width;
  o.height = a.height;
  o.dpi = a.dpi;
  std::vector<viz::Series> series;
  if (a.view == "energy") {
    RgbField B;
    auto solver = runSolver("bounces", system, a.maxIterations > 0 ? a.maxIterations : 12, 1e-12, B);
    viz::Series s{"power added by the bounce", {}, {}};
    const Eigen::VectorXd areas = c.mesh.areas();
    RgbField previous = RgbField::Zero(B.rows(), 3);
    for (const IterationRecord& r : solver->history()) {
      s.x.push_back(r.iteration);
      s.y.push_back(((r.B - previous).rowwise().sum().array() * areas.array()).sum());
      previous = r.B;
    }
    series.push_back(s);
    o.title = "Energy per bounce";
    o.xLabel = "bounce";
    o.yLabel = "power (W, sum of RGB)";
    o.logY = true;
    viz::writeLineChart(series, o, a.output);
    return;
  }
  const std::vector<std::string> names =
      a.solvers.empty() ? std::vector<std::string>{"jacobi", "gauss-seidel", "southwell", "progressive"}
                        : a.solvers;
  const bool time = a.view == "runtime-error" || a.xAxis == "time";
  for (const std::string& name : names) {
    RgbField B;
    auto solver = runSolver(name, system, a.maxIterations > 0 ? a.maxIterations : 60, 1e-10, B);
    viz::Series s{name, {}, {}};
    for (const IterationRecord& r : solver->history()) {
      s.x.push_back(time ? std::max(r.seconds, 1e-7) : r.iteration);
      s.y.push_back(r.residual);
    }
    series.push_back(s);
  }
  o.logY = true;
  o.logX = a.view == "runtime-error";
  o.yLabel = "relative residual |KB - E| / |E|";
  o.xLabel = time ? "time (s)" : "iteration";
  o.title = a.view == "runtime-error" ? "Run time against error" : "Convergence";
  viz::writeLineChart(series, o, a.output);
}

void run(const FigureArguments& a, CLI::App& command) {
  viz::figureFormatOf(a.output);  // reject an unknown extension before any computation
  if (!a.input.empty()) {
    if (a.view != "runtime-error") throw std::invalid_argument("--input belongs to the runtime-error view");
    timingTableFigure(a);
    std::cerr << "figure written to " << a.output << "\n";
    return;
  }
  Computed c;
  c.scene = loadSceneReportingWarnings(a.scene);
  c.mesh = buildMesh(c.scene, a.mesh.options());
  const bool refinedView = a.view == "links" || a.view == "discontinuity";
  for (auto [value, name] : {std::pair{refinedView ? -1 : a.element, "--element"},
                             {a.target, "--target"},
                             {a.row, "--row"},
                             {a.column, "--column"}})
    checkElement(value, c.mesh, name);
  if (a.view == "scene")
    sceneFigure(c, a, command);
  else if (a.view == "formfactor")
    formFactorFigure(c, a);
  else if (a.view == "matrix")
    matrixFigure(c, a);
  else if (a.view == "nusselt")
    nusseltFigure(c, a);
  else if (a.view == "hemicube")
    hemicubeFigure(c, a, command);
  else if (a.view == "rays")
    raysFigure(c, a, command);
  else if (a.view == "visibility")
    visibilityFigure(c, a);
  else if (a.view == "links")
    linksFigure(c, a);
  else if (a.view == "discontinuity")
    discontinuityFigure(c, a);
  else if (a.view == "convergence" || a.view == "runtime-error" || a.view == "energy")
    chartFigure(c, a);
  else
    throw std::invalid_argument("the view '" + a.view + "' is not available in this build");
  std::cerr << "figure written to " << a.output << "\n";
}
#endif

}  // namespace

void addFigureCommand(CLI::App& app) {
  auto a = std::make_shared<FigureArguments>();
  auto* command =
      app.add_subcommand("figure", "Render a view of a scene or of its numbers to PNG, SVG or PDF");
  command->add_option("scene", a->scene, "Scene file (.json or .obj)")->required()->check(CLI::ExistingFile);
  command
      ->add_option("--view", a->view,
                   "scene, formfactor, hemicube, nusselt, rays, matrix, convergence, runtime-error, energy, "
                   "visibility, links, discontinuity")
      ->capture_default_str()
      ->check(CLI::IsMember({"scene", "formfactor", "hemicube", "nusselt", "rays", "matrix", "convergence",
                             "runtime-error", "energy", "visibility", "links", "discontinuity"}));
  command->add_option("--output", a->output, "Figure file: .png, .svg or .pdf")->required();
  command->add_option("--width", a->width, "Width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 16384));
  command->add_option("--height", a->height, "Height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 16384));
  command->add_option("--dpi", a->dpi, "Scales fonts and lines (dpi/96); PDF page size")
      ->capture_default_str()
      ->check(CLI::Range(24.0, 1200.0));
  a->mesh.add(*command);
  addDeprecatedAlias(
      *command, "--formfactors",
      addSettingOption(*command, "method", a->formFactors)->default_str(defaultFormFactorMethod()));
  command->add_option(
      "--reference-formfactors", a->referenceFormFactors,
      "formfactor/matrix: show the difference to this method; scene --colour error: the reference");
  addSettingOption(*command, "solver", a->solver)->default_str("chosen by the scene's size");
  command
      ->add_option("--solvers", a->solvers,
                   "convergence, runtime-error: solvers to compare (comma-separated)")
      ->delimiter(',');
  addDeprecatedAlias(
      *command, "--max-iterations",
      addSettingOption(*command, "iterations", a->maxIterations)->default_str("the view's own"));
  addSettingOption(*command, "resolution", a->resolution);
  command->add_option("--samples", a->samples, "Ray samples (rays view, ray-cast methods)")
      ->capture_default_str();
  command
      ->add_option("--colour", a->colour,
                   "scene: radiosity, reflectance, emission, element, unshot, error; hemicube: items, delta")
      ->capture_default_str();
  command
      ->add_option("--error", a->errorMeasure,
                   "scene --colour error: relative (|B - B_ref| / B_ref), absolute (W/m^2) or brightest "
                   "(|B - B_ref| / the brightest reflecting B_ref)")
      ->capture_default_str()
      ->check(CLI::IsMember({"relative", "absolute", "brightest"}));
  addSettingOption(*command, "tone-map", a->toneMap);
  command->add_option("--exposure", a->exposure, "Exposure multiplier (0 = automatic)")
      ->capture_default_str();
  command->add_flag("--smooth", a->smooth, "Per-vertex interpolated shading");
  command->add_flag("--edges", a->edges, "Show mesh edges");
  command->add_flag("--no-gamma", a->noGamma, "Skip the sRGB encoding");
  command->add_flag("--log", a->logScale, "Log colour scale");
  command->add_flag("--no-colour-bar", a->noColourBar, "Hide the colour bar of scalar views");
  command->add_option("--colour-map", a->colourMap, "viridis, cividis or grey")->capture_default_str();
  command->add_option("--element", a->element, "The element the view is about (default: chosen)");
  command->add_option("--target", a->target, "nusselt, rays: the receiving element (default: an emitter)");
  command->add_option("--matrix", a->matrix, "matrix: F or K")
      ->capture_default_str()
      ->check(CLI::IsMember({"F", "K"}));
  command->add_option("--channel", a->channel, "matrix K: the colour channel, r, g or b")
      ->capture_default_str();
  command->add_option("--row", a->row, "matrix: highlighted row");
  command->add_option("--column", a->column, "matrix: highlighted column");
  command
      ->add_option(
          "--part", a->part,
          "nusselt: disk or hemisphere (auto: hemisphere for PNG); hemicube: faces or 3d (auto: faces)")
      ->capture_default_str();
  command->add_option(
      "--input", a->input,
      "runtime-error: draw this CSV of `bench formfactors` or `bench solvers` instead of timing "
      "the solvers now");
  command
      ->add_option("--mesh", a->refineMode,
                   "scene: the mesh of a refining solver (uniform, adaptive, discontinuity, hierarchical)")
      ->check(CLI::IsMember({"uniform", "adaptive", "discontinuity", "hierarchical"}));
  command->add_option("--link-colour", a->linkColour, "links: level or formfactor")
      ->capture_default_str()
      ->check(CLI::IsMember({"level", "formfactor"}));
  command
      ->add_option("--link-tolerance", a->refine.linkTolerance, "links, --mesh hierarchical: link threshold")
      ->capture_default_str();
  command->add_option("--max-elements", a->refine.maxElements, "--mesh adaptive: element budget")
      ->capture_default_str();
  command->add_option("--initial-edge", a->refine.initialMaxEdge,
                      "links, discontinuity, --mesh: starting max edge (0 = diagonal / 5)");
  command->add_option("--x", a->xAxis, "convergence: iteration or time")
      ->capture_default_str()
      ->check(CLI::IsMember({"iteration", "time"}));
  command->callback([a, command] {
#ifdef RT_HAVE_VIZ
    run(*a, *command);
#else
    throw std::runtime_error("'figure' needs the visualisation library (configure with RT_BUILD_VIZ=ON)");
#endif
  });
}

}  // namespace rt::cli
