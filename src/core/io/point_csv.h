// Query points as CSV: a header naming the columns x,y,z,nx,ny,nz (in any order, other columns ignored), then
// one point and the normal of the surface it lies on per line, in scene units. And the answers: one row per
// point, in the same order, with H and B per channel and their standard errors.
#pragma once

#include <string>
#include <vector>

#include "core/pathtrace/estimate.h"
#include "core/pathtrace/tracing_scene.h"

namespace rt {

// Throws InputError naming the file and line (and the column) for a missing column, a line with too few
// cells, a value that is not a finite number, or a zero normal. Normals are returned unit length.
std::vector<SurfacePoint> readSurfacePoints(const std::string& path);

// x,y,z,nx,ny,nz,surface,H_r,H_g,H_b,B_r,B_g,B_b,H_r_error,H_g_error,H_b_error,B_r_error,B_g_error,B_b_error,
// H_r_mesh_error,...,B_b_mesh_error. `surface` names the surface each point lies on (empty: none found, and B
// is 0). The *_error columns are Monte Carlo standard errors; the *_mesh_error columns the estimate of what
// the radiosity solution's mesh adds (0 where there is no mesh, as for the path tracer). With `breakdown`,
// H's parts follow (PointEstimate::HDirect...): H_r_direct,...,H_r_bounce,...,H_r_rest,... and the standard
// errors of the first two (H_r_direct_error,...,H_b_bounce_error). With `withErrorEstimate`, the error the
// query reports for H (errorEstimate: H_r_estimate,...) comes last.
void writePointEstimates(const std::string& path, const std::vector<SurfacePoint>& points,
                         const std::vector<PointEstimate>& estimates,
                         const std::vector<std::string>& surfaces, bool breakdown = false,
                         bool withErrorEstimate = false);

// Reads a file writePointEstimates wrote (the reference of a comparison), with H's parts where it has them.
std::vector<PointEstimate> readPointEstimates(const std::string& path);

}  // namespace rt
