// The two-pass point query of `radiosity irradiance`: H and B at the user's points on one mesh, their mesh
// error from a second pass on a mesh with elements twice the size, and, given a target error, the effort
// chosen from the query's own error estimates (gather rays and mesh).
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "cli/solution.h"
#include "core/pathtrace/estimate.h"
#include "core/pathtrace/tracing_scene.h"
#include "core/pathtrace/two_pass.h"

namespace rt::cli {

struct PointQuery {
  SolutionArguments solution;
  TwoPassOptions twoPass;
  bool meshError = true;   // estimate the mesh error from a second solve on a coarser mesh
  double targetError = 0;  // > 0: choose the effort for this RMS relative error of H (0.005 is 0.5 %)
};

// A target error as written on the command line, "0.5%" or 0.005: the fraction, or -1 when it is not a number
// in (0, 1).
double parseTargetError(const std::string& text);

// The two-pass estimates on `mesh`, reporting the solution's size and the times on stderr.
std::vector<PointEstimate> twoPassEstimates(const Scene& scene, const TracingScene& tracing,
                                            const MeshOptions& mesh, const PointQuery& query,
                                            const std::vector<SurfacePoint>& points);

// The estimates on `mesh`, with their mesh errors (HMeshError, BMeshError) when query.meshError asks for them
// and the mesh can be made coarser.
std::vector<PointEstimate> estimatesWithMeshError(const Scene& scene, const TracingScene& tracing,
                                                  const MeshOptions& mesh, const PointQuery& query,
                                                  const std::vector<SurfacePoint>& points);

// The RMS over the points and channels of a part of the error relative to H (points with H = 0 left out).
double relativeRms(const std::vector<PointEstimate>& estimates, Rgb PointEstimate::*part, double factor = 1);

// The query at query.targetError, the RMS over the points of H's error relative to H: pilot passes with few
// gather rays on the meshes h, 2h and 4h measure the noise (the standard errors, which fall as
// 1/sqrt(rays)) and the mesh error (by Richardson's extrapolation from the three, which more rays do not
// change); the mesh is refined while its error alone is over 0.6 of the target, then the gather rays are
// set so that the noise takes the rest. The secondary gather keeps its rays per hit (three balance its noise
// against the gather's at the least cost, whatever the total). Each point's HMeshError is the Richardson
// estimate; errorEstimate adds two standard errors. Reports its choice and its estimate on stderr.
std::vector<PointEstimate> estimatesForTarget(const Scene& scene, const TracingScene& tracing,
                                              const MeshOptions& mesh, const PointQuery& query,
                                              const std::vector<SurfacePoint>& points);

}  // namespace rt::cli
