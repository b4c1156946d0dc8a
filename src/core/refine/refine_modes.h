// The solvers behind solveRefined, one per mode. Options arrive validated and with every default filled in.
#pragma once

#include "core/refine/refine.h"

namespace rt {

RefinedSolution solveUniform(const Scene& scene, const RefineOptions& options, Progress& progress);
RefinedSolution solveAdaptive(const Scene& scene, const RefineOptions& options, Progress& progress);
RefinedSolution solveDiscontinuity(const Scene& scene, const RefineOptions& options, Progress& progress);
RefinedSolution solveHierarchical(const Scene& scene, const RefineOptions& options, Progress& progress);

}  // namespace rt
