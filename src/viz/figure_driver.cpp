#include "viz/figure_driver.h"
#include "core/io/scene_loader.h"

#include <stdexcept>

#include "core/assembly.h"
#include "viz/chart.h"
#include "viz/colour_map.h"
#include "viz/figure_driver_support.h"
#include "viz/figure_output.h"
#include "viz/matrix_view.h"
#include "viz/timing_table.h"

namespace rt::viz {
namespace detail {

void sceneFigure(const Computed& c, const FigureRequest& a) {
  SceneViewOptions o = sceneOptions(a);
  o.colouring = sceneColouringFromName(a.colour);
  o.errorMeasure = errorMeasureFromName(a.errorMeasure);
  SceneViewData data;
  if (!a.refineMode.empty()) {
    // The mesh a refining solver made, with its own radiosity (form factors and solver are its own).
    if (o.colouring == SceneColouring::Error || o.colouring == SceneColouring::UnshotPower)
      throw std::invalid_argument("--mesh shows radiosity, reflectance, emission or element colours");
    const RefinedSolution s = refined(c, a, refineModeFromString(a.refineMode));
    data.B = s.B;
    if (o.caption.empty()) o.caption = a.refineMode + " mesh: " + std::to_string(s.mesh.size()) + " elements";
    writeSceneFigure(s.mesh, c.scene.cameraOrDefault(), data, o, a.output);
    return;
  }
  const bool needsB = o.colouring == SceneColouring::Radiosity || o.colouring == SceneColouring::Error ||
                      o.colouring == SceneColouring::UnshotPower;
  if (needsB) {
    const FormFactorMatrix F = formFactors(c, a.formFactors, a);
    const RadiositySystem system = RadiositySystem::fromMesh(c.mesh, F);
    if (o.colouring == SceneColouring::UnshotPower) {
      // Unshot power after a few shots of progressive refinement.
      const int shots = a.maxIterations > 0 ? a.maxIterations : 8;
      auto solver = runSolver("progressive", system, shots, 1e-12, data.B);
      data.unshot = solver->history().back().unshot;
      o.caption = "unshot power after " + std::to_string(solver->iterations()) + " shots";
    } else if (o.colouring == SceneColouring::Error) {
      // Against the direct solution with the reference form factors: defaults show the error of 3 Jacobi
      // sweeps.
      const bool defaults = !a.solverGiven && !a.iterationsGiven && !a.referenceGiven;
      const std::string solver =
          defaults ? "jacobi" : (a.solver.empty() ? chooseSolver(c.mesh.size()) : a.solver);
      const int iterations = defaults ? 3 : a.maxIterations;
      runSolver(solver, system, iterations, 1e-12, data.B);
      const std::string refName = a.referenceFormFactors.empty() ? a.formFactors : a.referenceFormFactors;
      const FormFactorMatrix Fref = refName == a.formFactors ? F : formFactors(c, refName, a);
      const RadiositySystem refSystem = RadiositySystem::fromMesh(c.mesh, Fref);
      runSolver("direct", refSystem, 0, 1e-12, data.reference);
      o.caption = std::string(o.errorMeasure == ErrorMeasure::Relative      ? "relative "
                              : o.errorMeasure == ErrorMeasure::OfBrightest ? "brightest-relative "
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
  writeSceneFigure(c.mesh, c.scene.cameraOrDefault(), data, o, a.output);
}

void formFactorFigure(const Computed& c, const FigureRequest& a) {
  const int i = a.element >= 0 ? a.element : firstEmitter(c.mesh);
  const FormFactorMatrix F = formFactors(c, a.formFactors, a);
  SceneViewOptions o = sceneOptions(a);
  o.colouring = SceneColouring::Scalar;
  o.highlightElement = i;
  SceneViewData data;
  data.scalar = F.row(i).transpose();
  o.legend.title = "F_" + std::to_string(i) + ",j";
  o.caption = "form factors from element " + std::to_string(i) + " (" + a.formFactors + ")";
  if (!a.referenceFormFactors.empty()) {
    const FormFactorMatrix Fref = formFactors(c, a.referenceFormFactors, a);
    data.scalar = (F.row(i) - Fref.row(i)).cwiseAbs().transpose();
    o.legend.title = "|F - F_ref|";  // short: the colour bar is narrow
    o.caption =
        "|F_" + std::to_string(i) + "j| difference: " + a.formFactors + " against " + a.referenceFormFactors;
  }
  writeSceneFigure(c.mesh, c.scene.cameraOrDefault(), data, o, a.output);
}

void matrixFigure(const Computed& c, const FigureRequest& a) {
  const FormFactorMatrix F = formFactors(c, a.formFactors, a);
  MatrixViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  o.logScale = a.logScale || a.matrix == "F";
  o.map = colourMapFromName(a.colourMap);
  o.selectedRow = a.row;
  o.selectedColumn = a.column;
  for (const Element& e : c.mesh.elements) o.groups.push_back(e.patch);
  Eigen::MatrixXd shown = F;
  if (!a.referenceFormFactors.empty()) {
    shown = F - formFactors(c, a.referenceFormFactors, a);
    o.title = "F (" + a.formFactors + ") - F (" + a.referenceFormFactors + ")";
    o.valueLabel = "dF_ij";
  } else if (a.matrix == "K") {
    const int channel = a.channel;
    shown = Eigen::MatrixXd::Identity(F.rows(), F.cols()) -
            c.mesh.reflectance.col(channel).asDiagonal() * Eigen::MatrixXd(F);
    o.title = std::string("System matrix K = I - diag(rho) F (") + "RGB"[channel] + ")";
    o.valueLabel = "K_ij";
  } else {
    o.title = "Form factors F_ij (" + a.formFactors + ")";
  }
  writeMatrixFigure(shown, o, a.output);
}

void timingTable(const FigureRequest& a) {
  const TimingTable table = readTimingTable(a.input);
  ChartOptions o;
  o.width = a.width;
  o.height = a.height;
  o.dpi = a.dpi;
  o.logX = o.logY = true;
  o.title = "Run time against error";
  o.xLabel = "time (s)";
  o.yLabel = table.errorColumn == "rms_error" ? "RMS error of F" : table.errorColumn;
  writeLineChart(table.series, o, a.output);
}

void chartFigure(const Computed& c, const FigureRequest& a) {
  const FormFactorMatrix F = formFactors(c, a.formFactors, a);
  const RadiositySystem system = RadiositySystem::fromMesh(c.mesh, F);
  ChartOptions o;
  o.width = a.width;
  o.height = a.height;
  o.dpi = a.dpi;
  std::vector<Series> series;
  if (a.view == "energy") {
    RgbField B;
    auto solver = runSolver("bounces", system, a.maxIterations > 0 ? a.maxIterations : 12, 1e-12, B);
    Series s{"power added by the bounce", {}, {}};
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
    writeLineChart(series, o, a.output);
    return;
  }
  const std::vector<std::string> names =
      a.solvers.empty() ? std::vector<std::string>{"jacobi", "gauss-seidel", "southwell", "progressive"}
                        : a.solvers;
  const bool time = a.view == "runtime-error" || a.xAxis == "time";
  for (const std::string& name : names) {
    RgbField B;
    auto solver = runSolver(name, system, a.maxIterations > 0 ? a.maxIterations : 60, 1e-10, B);
    Series s{name, {}, {}};
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
  writeLineChart(series, o, a.output);
}

}  // namespace detail

void drawTimingTableFigure(const FigureRequest& a) {
  figureFormatOf(a.output);  // reject an unknown extension before any work
  if (a.view != "runtime-error") throw std::invalid_argument("--input belongs to the runtime-error view");
  detail::timingTable(a);
}

void drawFigure(const Scene& scene, const MeshOptions& meshOptions, const FigureRequest& a) {
  using namespace detail;
  figureFormatOf(a.output);  // reject an unknown extension before any computation
  const Computed c{scene, buildMesh(scene, meshOptions), Pipeline{}};
  const bool refinedView = a.view == "links" || a.view == "discontinuity";
  // Views of the solution need a light; views of geometry and form factors do not.
  if ((a.view == "scene" && a.colour == "radiosity") || a.view == "convergence" || a.view == "energy" ||
      refinedView)
    requireLight(scene);
  for (auto [value, name] : {std::pair{refinedView ? -1 : a.element, "--element"},
                             {a.target, "--target"},
                             {a.row, "--row"},
                             {a.column, "--column"}})
    checkElement(value, c.mesh, name);
  if (a.view == "scene")
    sceneFigure(c, a);
  else if (a.view == "formfactor")
    formFactorFigure(c, a);
  else if (a.view == "matrix")
    matrixFigure(c, a);
  else if (a.view == "nusselt")
    nusseltFigure(c, a);
  else if (a.view == "hemicube")
    hemicubeFigure(c, a);
  else if (a.view == "rays")
    raysFigure(c, a);
  else if (a.view == "visibility")
    visibilityFigure(c, a);
  else if (a.view == "links")
    linksFigure(c, a);
  else if (a.view == "discontinuity")
    discontinuityFigure(c, a);
  else if (a.view == "convergence" || a.view == "runtime-error" || a.view == "energy")
    chartFigure(c, a);
  else
    throw std::invalid_argument("unknown view '" + a.view + "'");
}

}  // namespace rt::viz
