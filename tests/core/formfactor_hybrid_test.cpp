// The "hybrid" method: which rule it uses for which pair, and that each rule is as accurate as it claims.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/formfactor/formfactor_method.h"
#include "core/formfactor/pair_matrix.h"
#include "formfactor_scenes.h"

namespace rt {
namespace {

using test::runMethod;

double radius(const Mesh& mesh, int e) {
  double r = 0;
  for (int v : mesh.elements[e].vertices)
    r = std::max(r, (mesh.vertices[v] - mesh.elements[e].centroid).norm());
  return r;
}

double rms(const FormFactorMatrix& a) {
  return std::sqrt(a.squaredNorm() / static_cast<double>(a.size()));
}

// In a convex box nothing is occluded, so no ray is cast and every entry is the unoccluded rule alone: exact
// for pairs closer than 3 radii; beyond, Lambert's formula from i's centroid (or, past 6 radii, the
// centroid-to-centroid kernel), a one-point rule over i whose error is second order in i's size, measured
// here as at most 0.75 (r_i + r_j)^2 / d^2 of the entry (checked against 1). Rows then sum to 1 within
// 1.6e-3 (checked against 5e-3).
TEST(HybridFormFactors, NearPairsAreExactAndFarPairsWithinTheCentroidRulesBound) {
  for (int subdivide : {3, 6}) {
    const Mesh mesh = test::meshOf(test::closedBox(1, 2, 3), subdivide);
    const FormFactorMatrix exact = runMethod("analytic", mesh);
    FormFactorStats stats;
    const FormFactorMatrix F = runMethod("hybrid", mesh, {}, &stats);
    EXPECT_EQ(stats.raysCast, 0u);
    int near = 0, far = 0;
    double worstRatio = 0;
    for (int i = 0; i < static_cast<int>(mesh.size()); ++i)
      for (int j = 0; j < static_cast<int>(mesh.size()); ++j) {
        if (i == j || exact(i, j) == 0) continue;
        const double d = (mesh.elements[j].centroid - mesh.elements[i].centroid).norm();
        const double reach = radius(mesh, i) + radius(mesh, j);
        const double error = std::abs(F(i, j) - exact(i, j));
        if (d < 3 * reach) {
          ++near;
          EXPECT_LE(error, 1e-12 * std::max(1.0, exact(i, j))) << i << " " << j;
        } else {
          ++far;
          worstRatio = std::max(worstRatio, error / (exact(i, j) * reach * reach / (d * d)));
        }
      }
    EXPECT_GT(near, 0);
    EXPECT_GT(far, 0);
    EXPECT_LT(worstRatio, 1.0) << subdivide;
    EXPECT_LT(diagnose(F, mesh.areas()).maxReciprocityError, 1e-12);
    EXPECT_LT(diagnose(F, mesh.areas()).maxClosureError, 5e-3) << subdivide;
  }
}

// With occluders the hidden part is a ray-cast estimate with rays in proportion to the pair's form factor:
// deterministic for a seed, more rays for more samples, and converging to the same matrix as raycast (RMS
// difference 8.6e-4, 2.2e-4, 4.9e-5 at 1, 16, 256 rays per 1 % of F; the largest 7e-4 at 256, checked
// against 2e-3).
TEST(HybridFormFactors, OccludedPairsConvergeAndAreDeterministicForASeed) {
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 4);
  FormFactorOptions options;
  options.samples = 1024;
  options.seed = 99;
  const FormFactorMatrix reference = runMethod("raycast", mesh, options);

  double previousError = 1e9;
  std::size_t previousRays = 0;
  for (int samples : {1, 16, 256}) {
    options.samples = samples;
    options.seed = 1;
    FormFactorStats stats;
    const FormFactorMatrix F = runMethod("hybrid", mesh, options, &stats);
    const double error = rms(F - reference);
    if (samples == 256) {
      EXPECT_LT((F - reference).cwiseAbs().maxCoeff(), 2e-3);
    }
    EXPECT_GT(stats.raysCast, previousRays) << samples;
    EXPECT_LT(error, previousError) << samples;
    previousError = error;
    previousRays = stats.raysCast;
    EXPECT_EQ((F - runMethod("hybrid", mesh, options)).cwiseAbs().maxCoeff(), 0.0);
    options.seed = 7;
    EXPECT_GT((F - runMethod("hybrid", mesh, options)).cwiseAbs().maxCoeff(), 0.0);
  }
}

}  // namespace
}  // namespace rt
