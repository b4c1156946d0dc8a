#include <cmath>
#include <stdexcept>

#include "core/formfactor/analytic.h"
#include "viz/colour_map.h"
#include "viz/display_pipeline.h"
#include "viz/figure_driver_support.h"

namespace rt::viz::detail {

Progress& progressOf(const FigureRequest& a) {
  return a.progress ? *a.progress : noProgress();
}

FormFactorMatrix formFactors(const Computed& c, const std::string& name, const FigureRequest& a) {
  FormFactorOptions options;
  options.hemicubeResolution = a.resolution;
  options.samples = a.samples;
  options.tolerance = a.formFactorTolerance;
  const auto cached = c.pipeline.formFactors(c.mesh, name, options, progressOf(a));
  say(a, "form factors (", name, "): ", cached->stats.summary());
  for (const std::string& w : cached->stats.warnings) say(a, "warning: ", w);
  return cached->F;
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

SceneViewOptions sceneOptions(const FigureRequest& a) {
  SceneViewOptions o;
  o.image.width = a.width;
  o.image.height = a.height;
  o.image.exposure = a.exposure;
  o.image.toneMap = toneMapFromName(a.toneMap);
  o.image.srgbGamma = !a.noGamma;
  o.image.smooth = a.smooth;
  o.image.showEdges = a.edges;
  o.legend.map = colourMapFromName(a.colourMap);
  o.legend.logScale = a.logScale;
  o.colourBar = !a.noColourBar;
  o.dpi = a.dpi;
  return o;
}

RefinedSolution refined(const Computed& c, const FigureRequest& a, RefineMode mode) {
  RefineOptions options = a.refine;
  options.mode = mode;
  Progress& progress = progressOf(a);
  RefinedSolution solution = solveRefined(c.scene, options, progress);
  say(a, "mesh: ", solution.stats.summary());
  return solution;
}

}  // namespace rt::viz::detail
