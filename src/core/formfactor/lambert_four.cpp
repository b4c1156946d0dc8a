#include "core/formfactor/lambert_four.h"

#include <algorithm>
#include <numbers>

#include "core/formfactor/analytic.h"

// The vector path needs GCC: clang (14) passes a declared function's __m256d arguments on the stack whatever
// its target attribute, where libmvec reads them from ymm0 and ymm1, so every lane would come back wrong.
#if defined(__x86_64__) && !defined(__clang__)
#define RT_LAMBERT_FOUR_AVX2 1
#include <immintrin.h>
// libmvec's four-lane atan2 for AVX2 (glibc 2.35 and later): the vector ABI name GCC itself would call.
extern "C" __attribute__((target("avx2"))) __m256d _ZGVdN4vv_atan2(__m256d y, __m256d x);
#endif

namespace rt {
namespace {

#if defined(RT_LAMBERT_FOUR_AVX2)
const bool kVectorised = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");

// Coordinate `axis` of corner index[p] of each polygon p, from its point.
__attribute__((target("avx2,fma"))) inline __m256d lanesOf(const Vec3* points, const Vec3* const* polygons,
                                                           const int* index, int axis) {
  return _mm256_setr_pd(
      polygons[0][index[0]][axis] - points[0][axis], polygons[1][index[1]][axis] - points[1][axis],
      polygons[2][index[2]][axis] - points[2][axis], polygons[3][index[3]][axis] - points[3][axis]);
}

__attribute__((target("avx2,fma"))) void sum4(const Vec3* points, const Vec3& normal,
                                              const Vec3* const* polygons, const int* counts, double* out) {
  const __m256d nx = _mm256_set1_pd(normal.x()), ny = _mm256_set1_pd(normal.y()),
                nz = _mm256_set1_pd(normal.z()), zero = _mm256_setzero_pd();
  const int longest = std::max(std::max(counts[0], counts[1]), std::max(counts[2], counts[3]));
  int index[4] = {0, 0, 0, 0};
  __m256d sum = zero;
  __m256d ax = lanesOf(points, polygons, index, 0), ay = lanesOf(points, polygons, index, 1),
          az = lanesOf(points, polygons, index, 2);
  for (int k = 0; k < longest; ++k) {
    // Edge k of each polygon: to its next corner, from its last back to its first, then first to first.
    for (int p = 0; p < 4; ++p) index[p] = k + 1 < counts[p] ? k + 1 : 0;
    const __m256d bx = lanesOf(points, polygons, index, 0), by = lanesOf(points, polygons, index, 1),
                  bz = lanesOf(points, polygons, index, 2);
    // c = a x b, |c| = |a||b| sin(theta), a . b = |a||b| cos(theta): as lambertSum() has them.
    const __m256d cx = _mm256_fmsub_pd(ay, bz, _mm256_mul_pd(az, by)),
                  cy = _mm256_fmsub_pd(az, bx, _mm256_mul_pd(ax, bz)),
                  cz = _mm256_fmsub_pd(ax, by, _mm256_mul_pd(ay, bx));
    const __m256d sine =
        _mm256_sqrt_pd(_mm256_fmadd_pd(cx, cx, _mm256_fmadd_pd(cy, cy, _mm256_mul_pd(cz, cz))));
    const __m256d cosine = _mm256_fmadd_pd(ax, bx, _mm256_fmadd_pd(ay, by, _mm256_mul_pd(az, bz)));
    const __m256d facing = _mm256_fmadd_pd(nx, cx, _mm256_fmadd_pd(ny, cy, _mm256_mul_pd(nz, cz)));
    const __m256d theta = _ZGVdN4vv_atan2(sine, cosine);
    // An edge seen edge-on, or of no length (sine 0), adds nothing: masked, as lambertSum() skips it.
    const __m256d term = _mm256_div_pd(_mm256_mul_pd(theta, facing), sine);
    sum = _mm256_add_pd(sum, _mm256_and_pd(term, _mm256_cmp_pd(sine, zero, _CMP_NEQ_OQ)));
    ax = bx, ay = by, az = bz;
  }
  _mm256_storeu_pd(out, _mm256_mul_pd(sum, _mm256_set1_pd(-0.5 / std::numbers::pi)));
  for (int p = 0; p < 4; ++p)
    if (counts[p] < 3) out[p] = 0;
}
#else
const bool kVectorised = false;
#endif

}  // namespace

bool lambertFourIsVectorised() {
  return kVectorised;
}

void lambertContourSum4(const Vec3* points, const Vec3& normal, const Vec3* const* polygons,
                        const int* counts, double* out) {
#if defined(RT_LAMBERT_FOUR_AVX2)
  if (kVectorised) {
    sum4(points, normal, polygons, counts, out);
    return;
  }
#endif
  for (int p = 0; p < 4; ++p)
    out[p] = counts[p] < 3 ? 0 : lambertContourSum(points[p], normal, polygons[p], counts[p]);
}

void lambertContourSum4(const Vec3* points, const Vec3& normal, const Vec3* corners, int stride, int count,
                        double* out) {
  const Vec3* polygons[4] = {corners, corners + stride, corners + 2 * stride, corners + 3 * stride};
  const int counts[4] = {count, count, count, count};
  lambertContourSum4(points, normal, polygons, counts, out);
}

}  // namespace rt
