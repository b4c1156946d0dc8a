// Lambert's contour sum at four points at once, each over its own polygon: the four points of a 2 x 2 rule
// over one receiver or over a cell whose hidden part keeps one form (ShadowClipper::HiddenForm), or the
// hidden pieces of four points. The arctangents dominate Lambert's sum; with AVX2 (in a GCC build) the four
// of each edge are one vector call (glibc's libmvec, within 4 ulp), otherwise the four sums are taken one by
// one. Polygons of fewer corners than the others are padded with their first corner, whose edges of no length
// add nothing.
#pragma once

#include "core/vec.h"

namespace rt {

// out[p] = lambertContourSum(points[p], normal, polygons[p], counts[p]), for p = 0..3. A count below 3 gives
// 0; its polygon's first corner must still be readable.
void lambertContourSum4(const Vec3* points, const Vec3& normal, const Vec3* const* polygons,
                        const int* counts, double* out);

// The same for polygons `stride` corners apart in one array (stride 0: one polygon for all four points).
void lambertContourSum4(const Vec3* points, const Vec3& normal, const Vec3* corners, int stride, int count,
                        double* out);

// Whether the vector path is taken on this machine.
bool lambertFourIsVectorised();

}  // namespace rt
