// The "quadrature" method: every entry within its absolute tolerance of the exact value, and a loose
// tolerance much cheaper than a tight one, counted in kernel evaluations (not time).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/formfactor/analytic.h"
#include "core/formfactor/formfactor_method.h"
#include "core/formfactor/quadrature/source_panels.h"
#include "formfactor_scenes.h"

namespace rt {
namespace {

using test::runMethod;

FormFactorOptions withTolerance(double tolerance) {
  FormFactorOptions options;
  options.tolerance = tolerance;
  return options;
}

double maxAbsDifference(const FormFactorMatrix& a, const FormFactorMatrix& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

// Two unit squares, parallel (one above the other) or perpendicular (sharing an edge), each split into
// N x N elements: every pair is unoccluded, so the analytic method is exact to ~1e-12.
Scene squares(bool parallel, double gap) {
  Scene s = test::emptyScene();
  test::addQuad(s, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0);
  if (parallel)
    test::addQuad(s, {0, 0, gap}, {0, 1, gap}, {1, 1, gap}, {1, 0, gap}, 0);
  else
    test::addQuad(s, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, 0);
  return s;
}

TEST(QuadratureMethod, IsRegisteredWithAToleranceKnob) {
  const auto names = formFactorMethodNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "quadrature"), names.end());
  const AccuracyKnob knob = accuracyKnobOf("quadrature");
  EXPECT_EQ(knob.field, AccuracyKnob::Field::Tolerance);
  EXPECT_EQ(knob.name, "ff-tolerance");
}

// A tolerance of 0 (FormFactorOptions' default) is the method's own, 1e-5: not the exact method's 1e-9,
// which made a solve that named the method without a tolerance take minutes.
TEST(QuadratureMethod, NoToleranceGivenMeansTheKnobsDefault) {
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 3);
  FormFactorStats unset, own, tight;
  const FormFactorMatrix F = runMethod("quadrature", mesh, withTolerance(0), &unset);
  const FormFactorMatrix G = runMethod("quadrature", mesh, withTolerance(1e-5), &own);
  runMethod("quadrature", mesh, withTolerance(1e-7), &tight);
  EXPECT_EQ(accuracyKnobOf("quadrature").defaultValue, 1e-5);
  EXPECT_EQ(unset.kernelEvaluations, own.kernelEvaluations);
  EXPECT_EQ(maxAbsDifference(F, G), 0.0);
  EXPECT_LT(own.kernelEvaluations, tight.kernelEvaluations);
}

TEST(QuadratureMethod, UnoccludedEntriesWithinTheTolerance) {
  for (bool parallel : {true, false})
    for (double gap : {0.5, 2.0}) {
      if (!parallel && gap > 0.5) continue;
      const Mesh mesh = test::meshOf(squares(parallel, gap), 6);
      const FormFactorMatrix exact = runMethod("analytic", mesh);
      for (double tolerance : {1e-3, 1e-5, 1e-7}) {
        FormFactorStats stats;
        const FormFactorMatrix F = runMethod("quadrature", mesh, withTolerance(tolerance), &stats);
        EXPECT_LE(maxAbsDifference(F, exact), tolerance)
            << (parallel ? "parallel" : "perpendicular") << " gap " << gap << " tolerance " << tolerance;
        EXPECT_EQ(stats.pairsUnoccluded, stats.pairsComputed);
        EXPECT_EQ(stats.raysCast, 0u);
      }
    }
}

// Far pairs may be integrated by one point on each side (the kernel at both one-point nodes) where the
// a-priori bound allows it on both: a small source facing a larger receiver (a square or a triangle), level
// or tilted, from near to far. The receiver's own size must count: with the source's alone, the larger
// receivers here would be off by several times the tolerance.
TEST(QuadratureMethod, FarPairsOnOnePointEachSideMeetTheTolerance) {
  for (double side : {0.1, 1.0})
    for (bool triangle : {false, true})
      for (double tilt : {0.0, 0.5})
        for (double height : {1.5, 3.0, 6.0, 12.0, 30.0}) {
          Scene s = test::emptyScene();
          test::addQuad(s, {0, 0, 0}, {side, 0, 0}, {side, side, 0}, {0, side, 0});
          // Facing down (towards the source), tilted about the x axis by `tilt` (rise over run).
          const Vec3 a(0.3, -0.5, height), b(0.3, 0.5, height + tilt), c(1.3, 0.5, height + tilt),
              d(1.3, -0.5, height);
          if (triangle) {
            Patch p;
            p.vertices = {a, b, c};
            const Vec3 n = newellNormal(p.vertices);
            p.normal = n.normalized();
            p.area = 0.5 * n.norm();
            p.surface = 0;
            s.patches.push_back(p);
          } else {
            test::addQuad(s, a, b, c, d);
          }
          const Mesh mesh = test::meshOf(s, 1);
          const FormFactorMatrix exact = runMethod("analytic", mesh);
          for (double tolerance : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
            const FormFactorMatrix F = runMethod("quadrature", mesh, withTolerance(tolerance));
            EXPECT_LE(maxAbsDifference(F, exact), tolerance)
                << "source " << side << (triangle ? ", triangle" : ", square") << " tilted " << tilt
                << " at height " << height << ", tolerance " << tolerance << ": F = " << exact(0, 1);
          }
        }
}

// A floor element wholly under the block sees nothing and nothing sees it: its row and column are exactly 0
// (they are settled before anything else; integrated, they came out as small errors up to 1e-6 on the grid
// room). Elements partly under it still exchange light with the room from the rest of their area. Finely
// meshed, the block (given without a bottom) must still be found a closed solid.
TEST(QuadratureMethod, ElementsUnderABlockExchangeNothing) {
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 10);  // floor elements 0.1 wide; the block 0.3..0.7
  FormFactorStats stats;
  const FormFactorMatrix F = runMethod("quadrature", mesh, withTolerance(1e-6), &stats);
  EXPECT_NE(stats.notes.find(" 1 closed convex solids"), std::string::npos) << stats.notes;
  int under = 0, beside = 0;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& element = mesh.elements[e];
    if (element.normal.z() < 0.99 || std::abs(element.centroid.z()) > 1e-9) continue;  // floor elements
    const double x = element.centroid.x(), y = element.centroid.y();
    const int k = static_cast<int>(e);
    if (x > 0.3 && x < 0.7 && y > 0.3 && y < 0.7) {
      ++under;
      EXPECT_EQ(F.row(k).cwiseAbs().maxCoeff(), 0.0) << "row " << k;
      EXPECT_EQ(F.col(k).cwiseAbs().maxCoeff(), 0.0) << "column " << k;
    } else if (x > 0.2 && x < 0.8 && y > 0.2 && y < 0.8) {
      ++beside;  // the ring around the block: it still sees the room
      EXPECT_GT(F.row(k).sum(), 0.3) << "row " << k;
    }
  }
  EXPECT_EQ(under, 16);
  EXPECT_EQ(beside, 20);
}

TEST(QuadratureMethod, ClosedBoxRowsSumToOne) {
  const Mesh mesh = test::meshOf(test::closedBox(1, 2, 3), 4);
  const double tolerance = 1e-6;
  const FormFactorMatrix F = runMethod("quadrature", mesh, withTolerance(tolerance));
  const FormFactorDiagnostics d = diagnose(F, mesh.areas());
  // Each of the n entries of a row errs by at most the tolerance; in practice they partly cancel.
  EXPECT_LT(d.maxClosureError, tolerance * static_cast<double>(mesh.size()));
  EXPECT_LT(d.maxClosureError, 1e-5);
  EXPECT_LT(d.maxReciprocityError, 1e-12);
  EXPECT_EQ(d.negativeEntries, 0);
}

// The a-priori order: a far panel at a loose tolerance takes the centroid rule, a tight tolerance or a near
// receiver takes more points, and a touching receiver cannot be integrated by a fixed rule at all.
TEST(QuadratureMethod, OrderFollowsDistanceAndTolerance) {
  const SourcePanel unit{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  auto receiverAt = [](double height) {
    return ReceiverBound{Vec3(0, 0, height), Vec3(0, 0, -1), Vec3(0.5, 0.5, height), std::sqrt(0.5), 1.0};
  };
  EXPECT_EQ(gaussOrderFor(unit, receiverAt(100), 1e-3), 1);
  EXPECT_GT(gaussOrderFor(unit, receiverAt(100), 1e-9), 1);
  EXPECT_GT(gaussOrderFor(unit, receiverAt(3), 1e-6), gaussOrderFor(unit, receiverAt(30), 1e-6));
  EXPECT_EQ(gaussOrderFor(unit, receiverAt(0), 1e-3), 0);
}

// The order read off for a triangle (the collapsed rule, as fans of cut sources use) meets the tolerance as
// a square's does, against the exact contour integral: the rule's Jacobian costs it one power of rho, which
// the bound takes into account (without it: 1.4 % of a floor-to-ceiling form factor lost on the grid room).
TEST(QuadratureMethod, TriangleOrderMeetsTheTolerance) {
  const std::vector<Vec3> receiver{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};  // at the height, facing down
  for (double height : {0.6, 1.5, 4.0, 20.0})
    for (double slope : {0.0, 0.6})             // the receiver's offset over its height
      for (int step = 0; step <= 16; ++step) {  // tolerances 1e-3 ... 1e-7, where each order takes over
        const double tolerance = std::pow(10.0, -3 - 0.25 * step);
        // A sliver and a fat triangle on the floor, facing up.
        for (const auto& corners : {std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0.5, 0.05, 0}},
                                    std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0.2, 0.9, 0}}}) {
          const double shift = slope * height;
          SourcePanel panel{corners[0] + Vec3(shift, 0, 0), corners[1] + Vec3(shift, 0, 0),
                            corners[2] + Vec3(shift, 0, 0)};
          std::vector<Vec3> up(receiver);
          for (Vec3& v : up) v.z() = height;
          const ReceiverBound bound{up[0], Vec3(0, 0, -1), Vec3(0.5, 0.5, height), std::sqrt(0.5), 1.0};
          const int n = gaussOrderFor(panel, bound, tolerance);
          if (n == 0) continue;  // split instead: the order is not the question
          double sum = 0;
          forEachGaussPoint(panel, n, [&](const Vec3& x, double w) {
            sum += w * lambertContourSum(x, Vec3(0, 0, 1), up.data(), 4);
          });
          const std::vector<Vec3> source = panel.toPolygon();
          const double exact = polygonToPolygonFormFactor(source.data(), 3, up.data(), 4) * panel.area();
          EXPECT_LE(std::abs(sum - exact), tolerance * panel.area())
              << "height " << height << " shift " << shift << " tolerance " << tolerance << " order " << n;
        }
      }
}

// The occluded room: against the unoccluded analytic matrix the quadrature method may only take away
// (occluders hide), never add, and the ceiling's rows, which nothing hides from behind, sum to about 1.
// Occluded entries do not yet meet the requested tolerance everywhere: a thin shadow that falls between all
// the points of a panel and its children goes unseen (measured here: 7.2e-4 between tolerances 1e-5 and
// 1e-7), and the hidden part's work bound stops some pairs early (ceiling rows 2.2e-5 from 1 at 1e-7). The
// bounds below are those measurements, rounded up, so that a regression shows; docs/formfactor-methods.md
// says so.
TEST(QuadratureMethod, OccludedRoomConvergesAndCloses) {
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 3);
  const FormFactorMatrix open = runMethod("analytic", mesh);
  FormFactorStats loose, tight;
  const FormFactorMatrix F5 = runMethod("quadrature", mesh, withTolerance(1e-5), &loose);
  const FormFactorMatrix F7 = runMethod("quadrature", mesh, withTolerance(1e-7), &tight);
  EXPECT_LT(loose.pairsUnoccluded, loose.pairsComputed);
  EXPECT_TRUE((F5.array() <= open.array() + 1e-5).all());
  EXPECT_LE(maxAbsDifference(F5, F7), 1e-3);
  EXPECT_LT(diagnose(F7, mesh.areas()).maxReciprocityError, 1e-12);
  // Ceiling elements (9..17 with 3 x 3 per face): rows of the exact matrix sum to 1.
  for (int i = 9; i < 18; ++i) EXPECT_NEAR(F7.row(i).sum(), 1.0, 3e-5) << i;
}

// A floor element and a ceiling element (the 2,400-wall grid room's 355 and 723) whose segments the tall
// Cornell block cuts near its corner only: the shadow grazes the receiver from a sliver of the source, and
// the panel's rule and its children's both saw almost none of it (4.33566e-4, 1.04e-5 too much, at every
// tolerance from 1e-5 to 1e-7). Reference: the exact method at 1e-9, 4.231160e-4 (4 M rays per pair:
// 4.2301e-4).
TEST(QuadratureMethod, FindsAShadowThatGrazesTheReceiverFromASliverOfTheSource) {
  Scene s = test::emptyScene();
  test::addQuad(s, {472.6, 0, 447.36}, {500.4, 0, 447.36}, {500.4, 0, 419.4}, {472.6, 0, 419.4});
  test::addQuad(s, {444.8, 548.8, 83.88}, {472.6, 548.8, 83.88}, {472.6, 548.8, 111.84},
                {444.8, 548.8, 111.84});
  const double x[4] = {423, 265, 314, 472}, z[4] = {247, 296, 456, 406};
  test::addQuad(s, {x[0], 330, z[0]}, {x[1], 330, z[1]}, {x[2], 330, z[2]}, {x[3], 330, z[3]});  // top
  for (int k = 0; k < 4; ++k) {
    const int n = (k + 1) % 4;
    test::addQuad(s, {x[k], 0, z[k]}, {x[n], 0, z[n]}, {x[n], 330, z[n]}, {x[k], 330, z[k]});
  }
  test::addQuad(s, {x[3], 0, z[3]}, {x[2], 0, z[2]}, {x[1], 0, z[1]}, {x[0], 0, z[0]});  // bottom
  const Mesh mesh = test::meshOf(s, 1);
  for (double tolerance : {1e-5, 1e-6}) {
    const FormFactorMatrix F = runMethod("quadrature", mesh, withTolerance(tolerance));
    EXPECT_NEAR(F(0, 1), 4.231160e-4, tolerance) << tolerance;
  }
}

// Cost is set by the tolerance: measured as kernel evaluations, so that the test does not depend on the
// machine or its load.
TEST(QuadratureMethod, LooseToleranceIsMuchCheaper) {
  for (const Scene& scene : {test::closedBox(1, 2, 3), test::roomWithBlock()}) {
    const Mesh mesh = test::meshOf(scene, 4);
    FormFactorStats loose, tight;
    runMethod("quadrature", mesh, withTolerance(1e-3), &loose);
    runMethod("quadrature", mesh, withTolerance(1e-6), &tight);
    EXPECT_GT(tight.kernelEvaluations, 3 * loose.kernelEvaluations)
        << loose.kernelEvaluations << " against " << tight.kernelEvaluations;
    EXPECT_EQ(tight.contourIntegrals, loose.contourIntegrals);  // the near pairs, exact at any tolerance
  }
}

}  // namespace
}  // namespace rt
