// Lambert's contour sum at four points at once, each over its own polygon of the same corner count: the four
// points of a 2 x 2 rule over a cell whose hidden part keeps one form (ShadowClipper::HiddenForm). The
// arctangents dominate Lambert's sum; with AVX2 the four of each edge are one vector call (glibc's libmvec,
// within 4 ulp), otherwise the four sums are taken one by one.
#pragma once

#include "core/vec.h"

namespace rt {

// out[p] = lambertContourSum(points[p], normal, corners + p * stride, count), for p = 0..3.
void lambertContourSum4(const Vec3* points, const Vec3& normal, const Vec3* corners, int stride, int count,
                        double* out);

// Whether the vector path is taken on this machine.
bool lambertFourIsVectorised();

}  // namespace rt
