#include "app/scene_settings.h"

#include <algorithm>

#include "core/solvers/local_lines_solver.h"
#include "core/solvers/solver.h"
#include "lesson/step_keys.h"

namespace rt::app {

void chooseSceneSolve(std::size_t polygons, lesson::StepParameters& p) {
  const AutomaticSolve automatic = chooseAutomaticSolve(polygons);
  if (automatic.formFactors) {
    p.solver = chooseSolver(polygons * 16);
    p.subdivide = 4;
    return;
  }
  constexpr long kMaxFirstIterationRays = 16'000'000;
  p.solver = automatic.solver;
  p.subdivide = 1;
  p.maxEdge.reset();
  p.raysPerIteration = static_cast<int>(std::min(localLinesDefaultRays(polygons), kMaxFirstIterationRays));
  // Stop when a thousandth of the light is left to shoot (the museum's benchmarks do): below that the rays'
  // noise (a few per cent per element at this budget) is larger than what is left, and every further
  // iteration keeps two more n x 3 fields for the replay (48 MB at a million elements).
  p.tolerance = 1e-3;
}

namespace {

// Whether `to` equals `from` but for the display keys and, with `lightToo`, the light and the reflectances.
bool sameBut(const lesson::StepParameters& from, const lesson::StepParameters& to, bool lightToo) {
  lesson::StepParameters shown = from;
  if (lightToo) {
    shown.lightScale = to.lightScale;
    shown.reflectance = to.reflectance;
  }
  shown.exposure = to.exposure;
  shown.toneMap = to.toneMap;
  shown.gamma = to.gamma;
  shown.smooth = to.smooth;
  shown.edges = to.edges;
  if (shown.reflectance.size() != to.reflectance.size()) return false;
  for (const auto& [surface, rho] : shown.reflectance) {
    const auto other = to.reflectance.find(surface);
    if (other == to.reflectance.end() || !(other->second == rho).all()) return false;
  }
  for (const lesson::StepKey& key : lesson::stepKeyTable())
    if (key.name != "reflectance" &&
        lesson::stepValueText(shown, key, key.name) != lesson::stepValueText(to, key, key.name))
      return false;
  return true;
}

}  // namespace

bool changesOnlyDisplay(const lesson::StepParameters& from, const lesson::StepParameters& to) {
  return sameBut(from, to, false);
}

bool changesOnlyLightOrDisplay(const lesson::StepParameters& from, const lesson::StepParameters& to) {
  return sameBut(from, to, true);
}

}  // namespace rt::app
