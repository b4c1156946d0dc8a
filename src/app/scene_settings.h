// The settings of a scene the reader opens (File > Open): how it is meshed and solved by default, and which
// later changes need no new solve.
#pragma once

#include <cstddef>

#include "lesson/lesson.h"

namespace rt::app {

// Mesh and solver for a scene of `polygons` polygons. A small scene is split 4 x 4 per polygon and solved
// with stored form factors. A large one (where `radiosity solve` switches to local lines) keeps one element
// per polygon, since a 4 x 4 split of the 50k museum would be 800k elements whose F needs 5 TB, and is
// solved by local lines with at most 16 M rays in the first iteration to a tolerance of 1e-3: under a minute
// on two cores at a million elements (docs/benchmarks.md), the reader raising the budget in the parameter
// panel when the noise shows.
void chooseSceneSolve(std::size_t polygons, lesson::StepParameters& p);

// True when `to` differs from `from` only in the display keys (exposure, tone map, gamma, smooth shading,
// mesh edges): the same solution, shown differently.
bool changesOnlyDisplay(const lesson::StepParameters& from, const lesson::StepParameters& to);
// The same, where the light and the reflectances may change too: the exposure in use is kept across such a
// change, so that the picture shows it.
bool changesOnlyLightOrDisplay(const lesson::StepParameters& from, const lesson::StepParameters& to);

}  // namespace rt::app
