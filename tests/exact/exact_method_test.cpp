// The "exact" method as the rest of the program sees it: registry, reciprocity, closure of an enclosure with
// boxes inside, facing-away pairs, progress and cancellation, cubature points for the lessons.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "core/formfactor/formfactor_method.h"
#include "exact/exact_reference.h"
#include "exact/exact_scenes.h"

namespace rt::exact {
namespace {

TEST(ExactMethod, RegistersUnderItsName) {
  registerExactMethod();
  const auto names = formFactorMethodNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "exact"), names.end());
  EXPECT_EQ(makeFormFactorMethod("exact")->name(), "exact");
}

// The unit room with two closed boxes floating inside: every element sees only fronts, so rows sum to 1.
Mesh roomWithClosedBoxes() {
  std::vector<Polygon> polygons = test::roomFaces({0, 0, 0}, {1, 1, 1});
  for (const Polygon& f : test::boxFaces({0.2, 0.1, 0.2}, {0.45, 0.4, 0.5}, true)) polygons.push_back(f);
  for (const Polygon& f : test::boxFaces({0.55, 0.5, 0.45}, {0.8, 0.7, 0.8}, true)) polygons.push_back(f);
  return test::meshFromPolygons(polygons);
}

TEST(ExactMethod, EnclosureWithInnerBoxesHasUnitRowSums) {
  registerExactMethod();
  const Mesh mesh = roomWithClosedBoxes();
  FormFactorOptions options;
  options.tolerance =
      1e-4;  // keeps the test fast; rows then sum to 1 within ~1e-4 (estimates are pessimistic)
  FormFactorStats stats;
  std::vector<double> fractions;
  CallbackProgress progress([&](double f, const std::string&) { fractions.push_back(f); });
  const FormFactorMatrix F = makeFormFactorMethod("exact")->compute(mesh, options, progress, stats);
  const Eigen::VectorXd areas = mesh.areas();
  for (Eigen::Index i = 0; i < F.rows(); ++i) {
    EXPECT_NEAR(F.row(i).sum(), 1.0, 1e-4) << "row " << i;
    EXPECT_EQ(F(i, i), 0.0);
    for (Eigen::Index j = 0; j < F.cols(); ++j) {
      EXPECT_GE(F(i, j), 0.0);
      EXPECT_NEAR(areas[i] * F(i, j), areas[j] * F(j, i), 1e-15);
    }
  }
  EXPECT_EQ(stats.elements, mesh.size());
  EXPECT_GT(stats.pairsSkippedFacing, 0u);  // e.g. opposite faces of one box
  EXPECT_GT(stats.pairsUnoccluded, 0u);
  EXPECT_LT(stats.pairsUnoccluded, stats.pairsComputed);
  EXPECT_EQ(stats.pairsByReciprocity, stats.pairsComputed);
  ASSERT_FALSE(fractions.empty());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  // Box faces touching nothing see the room and the other box: check one against the sum rule directly.
  const FormFactorDiagnostics d = diagnose(F, areas);
  EXPECT_LT(d.maxClosureError, 1e-4);
  EXPECT_EQ(d.negativeEntries, 0);
}

TEST(ExactMethod, FacingAwayPairsAreZeroWithoutWork) {
  // Two squares back to back.
  const Mesh mesh = test::meshFromPolygons(
      {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 0, -1}, {0, 1, -1}, {1, 1, -1}, {1, 0, -1}}});
  const EntryResult entry = elementFormFactor(mesh, 0, 1);
  EXPECT_FALSE(entry.facing);
  EXPECT_EQ(entry.value, 0.0);
  EXPECT_EQ(entry.evaluations, 0);
}

TEST(ExactMethod, CancelThrows) {
  const Mesh mesh = roomWithClosedBoxes();
  CallbackProgress progress(nullptr);
  progress.cancel();
  EXPECT_THROW(exactFormFactors(mesh, exactOptionsFor(1e-4), progress), Cancelled);
}

// A budget of point evaluations ends the run with a message that names it, instead of hours of work.
TEST(ExactMethod, WorkBudgetEndsTheRunWithAMessageNamingIt) {
  registerExactMethod();
  const Mesh mesh = roomWithClosedBoxes();
  FormFactorOptions options;
  options.tolerance = 1e-6;
  options.workBudget = 2000;
  FormFactorStats stats;
  try {
    makeFormFactorMethod("exact")->compute(mesh, options, noProgress(), stats);
    FAIL() << "the budget did not stop the run";
  } catch (const WorkBudgetExceeded& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("work budget of 2000 point evaluations (--ff-budget) ran out"), std::string::npos)
        << message;
    EXPECT_NE(message.find("element pairs"), std::string::npos) << message;
  }
}

// Progress follows the point evaluations, within rows too: it never goes back and ends at 1.
TEST(ExactMethod, ProgressMovesWithTheWorkAndEndsAtOne) {
  const Mesh mesh = roomWithClosedBoxes();
  std::vector<double> fractions;
  CallbackProgress progress([&](double f, const std::string&) { fractions.push_back(f); });
  exactFormFactors(mesh, exactOptionsFor(1e-6), progress, nullptr, 1);
  ASSERT_GE(fractions.size(), mesh.size());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_GT(fractions[fractions.size() / 2], 0.0);
}

TEST(ExactMethod, CubaturePointsReproduceTheEntry) {
  const Mesh mesh = roomWithClosedBoxes();
  // Floor (patch 0 faces +x ... find the floor: normal +y) to ceiling, occluded by both boxes.
  int floor = -1, ceiling = -1;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    if (mesh.elements[e].normal.y() > 0.5 && mesh.elements[e].centroid.y() < 1e-9)
      floor = static_cast<int>(e);
    if (mesh.elements[e].normal.y() < -0.5 && mesh.elements[e].centroid.y() > 1 - 1e-9)
      ceiling = static_cast<int>(e);
  }
  ASSERT_GE(floor, 0);
  ASSERT_GE(ceiling, 0);
  const ExactOptions options = exactOptionsFor(1e-4);
  std::vector<CubaturePoint> points;
  const EntryResult entry = elementFormFactor(mesh, floor, ceiling, options, &points);
  EXPECT_TRUE(entry.occluded);
  double weight = 0, integral = 0;
  for (const CubaturePoint& p : points) {
    weight += p.weight;
    integral += p.weight * p.value;
  }
  EXPECT_NEAR(weight, mesh.elements[floor].area, 1e-12);
  EXPECT_NEAR(integral / mesh.elements[floor].area, entry.value, 1e-14);
  EXPECT_LT(entry.value, 0.19982489569838738);  // the boxes take their share of the unoccluded C-11 value
  EXPECT_GT(entry.value, 0.1);
}

TEST(ExactMethod, TheSameSceneInAnotherUnitGivesTheSameEntriesForTheSameWork) {
  // Metres or millimetres: tolerances, margins and the floor for tiny entries are all relative, so the work
  // and the result agree (up to rounding steering the adaptive refinement a little differently).
  auto scaled = [](std::vector<Polygon> polygons, double factor) {
    for (Polygon& p : polygons)
      for (Vec3& v : p) v *= factor;
    return polygons;
  };
  const ExactOptions options = exactOptionsFor(1e-6);
  // Two 1 cm squares 10 m apart: F ~ 3e-7, below the floor of 1e-6, in both units.
  const std::vector<Polygon> far{test::axisRectangle(2, 0, {0, 0, 0}, {0.01, 0.01, 0}, true),
                                 test::axisRectangle(2, 10, {0, 0, 10}, {0.01, 0.01, 10}, false)};
  const EntryResult m = elementFormFactor(test::meshFromPolygons(far), 0, 1, options);
  const EntryResult mm = elementFormFactor(test::meshFromPolygons(scaled(far, 1000)), 0, 1, options);
  EXPECT_NEAR(m.value, 1e-4 / (std::numbers::pi * 100), 1e-3 * m.value);
  EXPECT_NEAR(mm.value, m.value, 1e-6 * m.value);
  EXPECT_EQ(mm.evaluations, m.evaluations);

  std::vector<Polygon> room = test::roomFaces({0, 0, 0}, {1, 1, 1});
  for (const Polygon& f : test::boxFaces({0.2, 0.1, 0.2}, {0.45, 0.4, 0.5}, true)) room.push_back(f);
  const Mesh unit = test::meshFromPolygons(room, 2),
             millimetres = test::meshFromPolygons(scaled(room, 1000), 2);
  // A floor above every entry makes all targets absolute: they must scale with the unit too.
  ExactOptions floored = exactOptionsFor(1e-3);
  floored.absoluteFloor = 0.5;
  int occluded = 0;
  for (const ExactOptions& o : {options, floored})
    for (int source = 0; source < 8; ++source)
      for (int receiver = 8; receiver < static_cast<int>(unit.size()); receiver += 5) {
        const EntryResult a = elementFormFactor(unit, source, receiver, o);
        const EntryResult b = elementFormFactor(millimetres, source, receiver, o);
        occluded += a.occluded ? 1 : 0;
        EXPECT_EQ(a.occluded, b.occluded);
        EXPECT_NEAR(a.value, b.value, 2 * o.tolerance * std::max(a.value, o.absoluteFloor) + 1e-12)
            << source << " -> " << receiver;
        EXPECT_NEAR((b.evaluations + 1.0) / (a.evaluations + 1.0), 1.0, 0.5);
      }
  EXPECT_GT(occluded, 0);
}

TEST(ExactMethod, ErrorMapIsTheAbsoluteDifference) {
  FormFactorMatrix a(2, 2), b(2, 2);
  a << 0, 0.5, 0.25, 0;
  b << 0, 0.4, 0.3, 0;
  const Eigen::MatrixXd e = errorMap(a, b);
  EXPECT_NEAR(e(0, 1), 0.1, 1e-15);
  EXPECT_NEAR(e(1, 0), 0.05, 1e-15);
  EXPECT_THROW(errorMap(a, FormFactorMatrix(3, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace rt::exact
