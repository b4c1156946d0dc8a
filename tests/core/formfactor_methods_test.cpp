// Every registered form-factor method on meshes: closure in closed boxes, reciprocity, agreement with the
// analytic matrix, skip rules, determinism. Tolerances follow each method's convergence rate (see the comment
// at each).
#include <gtest/gtest.h>

#include "core/formfactor/analytic.h"
#include "core/formfactor/formfactor_method.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/shaft_culling.h"
#include "formfactor_scenes.h"

namespace rt {
namespace {

using test::runMethod;

double maxAbsDifference(const FormFactorMatrix& a, const FormFactorMatrix& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

TEST(FormFactorMethods, AllBuiltinsAreRegistered) {
  const auto names = formFactorMethodNames();
  for (const char* name :
       {"analytic", "analytic-visibility", "raycast", "hemicube", "montecarlo", "nusselt", "hybrid"})
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  EXPECT_THROW(makeFormFactorMethod("no-such-method"), std::invalid_argument);
}

TEST(FormFactorMethods, AnalyticRowsSumToOneInClosedBoxes) {
  for (const Scene& scene : {test::closedBox(1, 1, 1), test::closedBox(1, 2, 3)})
    for (int subdivide : {1, 3}) {
      const Mesh mesh = test::meshOf(scene, subdivide);
      FormFactorStats stats;
      const FormFactorMatrix F = runMethod("analytic", mesh, {}, &stats);
      const auto d = diagnose(F, mesh.areas());
      EXPECT_LT(d.maxClosureError, 1e-9) << subdivide;
      EXPECT_LT(d.maxReciprocityError, 1e-12);
      EXPECT_EQ(d.negativeEntries, 0);
      EXPECT_EQ(stats.raysCast, 0u);  // convex enclosure: no visibility work at all
    }
}

TEST(FormFactorMethods, AnalyticMatchesReferenceCubeFaces) {
  const Mesh mesh = test::meshOf(test::closedBox(1, 1, 1), 1);
  const FormFactorMatrix F = runMethod("analytic", mesh);
  EXPECT_NEAR(F(0, 1), 0.19982489569838738, 1e-15);  // opposite faces (Howell C-11)
  EXPECT_NEAR(F(0, 2), 0.20004377607540316, 1e-15);  // adjacent faces (Howell C-14)
}

TEST(FormFactorMethods, SkipRulesFireWhereTheyShouldAndNeverChangeTheResult) {
  const Mesh mesh = test::meshOf(test::closedBox(1, 2, 3), 2);
  FormFactorStats stats;
  const FormFactorMatrix F = runMethod("analytic", mesh, {}, &stats);
  // Each face is 2 x 2 elements: pairs on the same face (6 faces x 6 pairs) face away; everything else is
  // computed once and mirrored.
  const std::size_t n = mesh.size(), pairs = n * (n - 1) / 2;
  EXPECT_EQ(stats.pairsSkippedFacing, 6u * 6u);
  EXPECT_EQ(stats.pairsComputed, pairs - 36u);
  EXPECT_EQ(stats.pairsByReciprocity, stats.pairsComputed);
  EXPECT_EQ(stats.pairsUnoccluded, stats.pairsComputed);
  FormFactorStats plainStats;
  const FormFactorMatrix plain = computeReciprocalMatrix(
      mesh, {}, noProgress(), plainStats, "test",
      [&](int i, int j) {
        PairResult r;
        r.value = polygonToPolygonFormFactor(mesh.polygon(i), mesh.polygon(j));
        return r;
      },
      false);
  EXPECT_EQ(plainStats.pairsSkippedFacing, 0u);
  EXPECT_EQ(plainStats.pairsComputed, n * (n - 1));
  EXPECT_LT(maxAbsDifference(F, plain), 1e-14);
}

TEST(FormFactorMethods, ShaftTestFindsOnlyPairsAroundTheBlock) {
  const Mesh room = test::meshOf(test::closedBox(1, 1, 1), 2);
  const ShaftCulling roomShafts(room);
  EXPECT_FALSE(roomShafts.anyOccluder());
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 2);
  const ShaftCulling shafts(mesh);
  EXPECT_TRUE(shafts.anyOccluder());
  // Floor element under the block's footprint corner and the ceiling element above it: the block is in the
  // way. Elements 0..3 are the floor, 4..7 the ceiling (2 x 2 each).
  bool anyFloorCeiling = false;
  for (int i = 0; i < 4; ++i)
    for (int j = 4; j < 8; ++j) anyFloorCeiling |= shafts.mayBeOccluded(i, j);
  EXPECT_TRUE(anyFloorCeiling);
  // Two walls meeting at an edge: nothing can be between them (the block is below both... but in the shaft of
  // adjacent walls only if it crosses their planes' wedge, which it does not).
}

TEST(FormFactorMethods, VisibilityReducesOccludedPairsOnly) {
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 2);
  FormFactorOptions options;
  options.samples = 64;
  FormFactorStats stats;
  const FormFactorMatrix open = runMethod("analytic", mesh);
  const FormFactorMatrix shadowed = runMethod("analytic-visibility", mesh, options, &stats);
  EXPECT_GT(stats.raysCast, 0u);
  EXPECT_LT(shadowed.sum(), open.sum());
  EXPECT_TRUE((shadowed.array() <= open.array() + 1e-15).all());
  // Closure from the ceiling (elements 4..7), which sees walls, floor and block top and nothing from behind:
  // rows of the visibility-aware matrix still sum to about 1. Visible fractions from 64 rays have a standard
  // error
  // <= 0.5/8 per pair, but only the few pairs grazing the block's edges are partly visible and their errors
  // partly cancel over a row: 0.03.
  for (int i = 4; i < 8; ++i) EXPECT_NEAR(shadowed.row(i).sum(), 1.0, 0.03) << i;
}

TEST(FormFactorMethods, IgnoringOccludersOnAnOccludedSceneWarns) {
  // The block hides part of the ceiling from the floor: analytic counts that light anyway, so floor rows sum
  // above 1. Both facts are warnings in the stats every command prints; the visibility-aware method has none.
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 2);
  FormFactorStats open, shadowed, closed;
  runMethod("analytic", mesh, {}, &open);
  ASSERT_EQ(open.warnings.size(), 2u);
  EXPECT_GT(open.pairsOccludersIgnored, 0u);
  EXPECT_NE(open.warnings[0].find("analytic ignored occluders for"), std::string::npos) << open.warnings[0];
  EXPECT_NE(open.warnings[1].find("rows of F sum to more than 1"), std::string::npos) << open.warnings[1];
  FormFactorOptions rays;
  rays.samples = 256;  // visibility noise well under the 1 % a ray-cast row may overshoot without a warning
  runMethod("analytic-visibility", mesh, rays, &shadowed);
  EXPECT_TRUE(shadowed.warnings.empty()) << shadowed.warnings.front();
  // Where nothing can be occluded, analytic is exact and says nothing.
  runMethod("analytic", test::meshOf(test::closedBox(1, 2, 3), 2), {}, &closed);
  EXPECT_TRUE(closed.warnings.empty()) << closed.warnings.front();
}

// The row-sum warning allows for the error a method states per entry (quadrature: its tolerance on each
// one), so a correct run is silent at every tolerance; an overshoot beyond it names the rows.
TEST(FormFactorMethods, RowSumsWarnOnlyBeyondTheMethodsStatedErrorAndNameTheRows) {
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 3);
  for (double tolerance : {1e-2, 1e-3, 1e-5}) {
    FormFactorOptions options;
    options.tolerance = tolerance;
    FormFactorStats stats;
    runMethod("quadrature", mesh, options, &stats);
    EXPECT_TRUE(stats.warnings.empty()) << tolerance << ": " << stats.warnings.front();
  }
  FormFactorStats open;
  const FormFactorMatrix F = runMethod("analytic", mesh, {}, &open);
  ASSERT_EQ(open.warnings.size(), 2u);
  Eigen::Index first = 0;
  while (first < F.rows() && F.row(first).sum() <= 1 + 1e-6) ++first;
  ASSERT_LT(first, F.rows());
  EXPECT_NE(open.warnings[1].find("elements " + std::to_string(first)), std::string::npos)
      << open.warnings[1];
}

TEST(FormFactorMethods, ElementsThatSeeNothingAreNamedAndLeftOutOfTheRowSums) {
  // A closed room with a solid block, bottom included: the bottom lies on the floor facing it and sees
  // nothing, and so does the floor element entirely under the block. Both are right; the summary names them
  // instead of reporting a row sum of 0 and a closure error of 1.
  Scene s = test::closedBox(1, 1, 1);
  test::addBox(s, Vec3(0.3, 0.3, 0), Vec3(0.7, 0.7, 0.4), true);
  const Mesh mesh = test::meshOf(s, 5);
  const FormFactorDiagnostics d = diagnose(runMethod("analytic-visibility", mesh), mesh.areas());
  EXPECT_EQ(d.blindRows, 25 + 1);  // the bottom's 5 x 5 elements and the floor's element [0.4, 0.6]^2
  EXPECT_EQ(d.blindExamples.size(), 5u);
  EXPECT_GT(d.minRowSum, 0.1);
  EXPECT_NE(d.summary().find("26 elements see nothing (hidden or enclosed, e.g. "), std::string::npos)
      << d.summary();
}

// raycast: without occluders the estimator is a stratified quadrature of Lambert's point formula, which is
// bounded but has a logarithmic derivative at edges shared with j: jittered sampling then converges like N^-1
// (not N^-3/2). With N = 64 the measured worst entry error is ~1e-2 for adjacent elements, so entries are
// checked to 2e-2 and row sums to 2e-2.
TEST(FormFactorMethods, RaycastConvergesToAnalyticInAConvexBox) {
  const Mesh mesh = test::meshOf(test::closedBox(1, 2, 3), 2);
  FormFactorOptions options;
  options.samples = 64;
  const FormFactorMatrix exact = runMethod("analytic", mesh);
  FormFactorStats stats;
  const FormFactorMatrix F = runMethod("raycast", mesh, options, &stats);
  EXPECT_EQ(stats.raysCast, 0u);
  EXPECT_LT(maxAbsDifference(F, exact), 2e-2);
  EXPECT_LT(diagnose(F, mesh.areas()).maxClosureError, 2e-2);
  EXPECT_LT(diagnose(F, mesh.areas()).maxReciprocityError, 1e-12);  // reciprocity by construction
  // Deterministic for a seed, different for another.
  EXPECT_EQ(maxAbsDifference(F, runMethod("raycast", mesh, options)), 0.0);
  options.seed = 7;
  EXPECT_GT(maxAbsDifference(F, runMethod("raycast", mesh, options)), 0.0);
}

// montecarlo: each entry is a binomial proportion, standard error sqrt(F(1-F)/N). With N = 20000 rays per
// element and F <= 0.3 that is <= 0.0033; 5 sigma = 0.017. Every ray from a closed box hits a wall, so rows
// sum to 1 except for the odd ray that slips through a corner in Embree's single-precision geometry (one in
// 20000 here): 1e-3.
TEST(FormFactorMethods, MonteCarloIsUnbiasedWithinItsStandardError) {
  const Mesh mesh = test::meshOf(test::closedBox(1, 2, 3), 1);
  FormFactorOptions options;
  options.samples = 20000;
  const FormFactorMatrix exact = runMethod("analytic", mesh);
  FormFactorStats stats;
  const FormFactorMatrix F = runMethod("montecarlo", mesh, options, &stats);
  EXPECT_LT(maxAbsDifference(F, exact), 0.017);
  EXPECT_GT(stats.standardError, 0.0);
  EXPECT_LT(stats.standardError, 0.004);
  EXPECT_LT(diagnose(F, mesh.areas()).maxClosureError, 1e-3);
  EXPECT_EQ(maxAbsDifference(F, runMethod("montecarlo", mesh, options)), 0.0);
}

// hemicube: the centroid-point approximation dominates for face-sized elements (about 5e-2 for adjacent faces
// of a cube), while aliasing adds O(1/res) per edge crossing; with res 256 the matrix is within 0.06 of
// analytic and, since the delta form factors sum to 1 and every pixel sees a wall, rows sum to 1 to rounding.
TEST(FormFactorMethods, HemicubeApproachesAnalyticAndClosesRows) {
  const Mesh mesh = test::meshOf(test::closedBox(1, 1, 1), 1);
  FormFactorOptions options;
  options.hemicubeResolution = 256;
  const FormFactorMatrix F = runMethod("hemicube", mesh, options);
  EXPECT_LT(maxAbsDifference(F, runMethod("analytic", mesh)), 0.06);
  EXPECT_LT(diagnose(F, mesh.areas()).maxClosureError, 1e-12);
  // Finer elements: the centroid approximation improves (error of the point rule ~ (size/distance)^2).
  const Mesh fine = test::meshOf(test::closedBox(1, 2, 3), 4);
  const FormFactorMatrix Ff = runMethod("hemicube", fine, options);
  EXPECT_LT(diagnose(Ff, fine.areas()).maxClosureError, 1e-9);
}

// nusselt: from the centroid; with 64 segments per arc the outline area is within ~(pi/64)^2/6 relative of
// the exact disk area, so rows match the centroid Lambert values to ~1e-3 and close to about that.
TEST(FormFactorMethods, NusseltRowsMatchCentroidLambert) {
  const Mesh mesh = test::meshOf(test::closedBox(1, 2, 3), 2);
  FormFactorOptions options;
  options.samples = 64;
  const FormFactorMatrix F = runMethod("nusselt", mesh, options);
  for (int i = 0; i < static_cast<int>(mesh.size()); ++i)
    for (int j = 0; j < static_cast<int>(mesh.size()); ++j) {
      const double lambert = i == j ? 0
                                    : pointToPolygonFormFactor(mesh.elements[i].centroid,
                                                               mesh.elements[i].normal, mesh.polygon(j));
      EXPECT_NEAR(F(i, j), lambert, 1e-3 * std::max(lambert, 1e-3));
    }
  EXPECT_LT(diagnose(F, mesh.areas()).maxClosureError, 2e-3);
}

TEST(FormFactorMethods, CancellationThrows) {
  const Mesh mesh = test::meshOf(test::closedBox(1, 1, 1), 2);
  CallbackProgress progress(nullptr);
  progress.cancel();
  FormFactorStats stats;
  for (const char* name : {"analytic", "raycast", "hemicube", "montecarlo", "nusselt", "hybrid"})
    EXPECT_THROW(makeFormFactorMethod(name)->compute(mesh, {}, progress, stats), Cancelled) << name;
}

}  // namespace
}  // namespace rt
