// Which way each pair went through the quadrature method's stages (formfactor/quadrature/README.md): the
// routes counted in the method's notes, and one pair explained (`radiosity formfactors --explain I,J`): an
// enclosed pair, a far pair and an occluded one, each with the value the matrix holds.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <string>

#include "core/formfactor/quadrature/pair_explanation.h"
#include "core/io/scene_loader.h"
#include "formfactor_scenes.h"
#include "support/test_paths.h"

namespace rt {
namespace {

// A closed unit room with a solid block (bottom included) on the floor, 5 x 5 per face: the floor element
// under the block's middle lies inside it, the ceiling and floor see each other past it.
Mesh roomWithSolidBlock() {
  Scene s = test::closedBox(1, 1, 1);
  test::addBox(s, Vec3(0.3, 0.3, 0), Vec3(0.7, 0.7, 0.4), true);
  return test::meshOf(s, 5);
}

std::map<std::string, long> routesIn(const std::string& notes) {
  std::map<std::string, long> routes;
  const auto start = notes.find("routes: ");
  if (start == std::string::npos) return routes;
  const std::string list = notes.substr(start + 8, notes.find(';', start) - start - 8);
  const std::regex entry("([a-z-]+) ([0-9]+)");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), entry); it != std::sregex_iterator(); ++it)
    routes[(*it)[1]] = std::stol((*it)[2]);
  return routes;
}

TEST(QuadratureRoutes, EveryComputedPairIsCountedOnceUnderItsRoute) {
  const Mesh mesh = roomWithSolidBlock();
  FormFactorStats stats;
  test::runMethod("quadrature", mesh, {}, &stats);
  const auto routes = routesIn(stats.notes);
  ASSERT_FALSE(routes.empty()) << stats.notes;
  long total = 0;
  for (const auto& [name, count] : routes) total += count;
  EXPECT_EQ(total, static_cast<long>(stats.pairsComputed)) << stats.notes;
  for (const char* expected : {"enclosed", "far-unoccluded", "unoccluded"})
    EXPECT_GT(routes.count(expected) ? routes.at(expected) : 0, 0) << expected << " in " << stats.notes;
  EXPECT_GT(routes.count("cells") ? routes.at("cells") : 0, 0) << stats.notes;
}

// The first pair of the mesh, in row order, that takes `route`, explained; -1 in i when none does.
PairExplanation firstOn(const Mesh& mesh, QuadratureExplainer& explain, QuadratureRoute route) {
  const int n = static_cast<int>(mesh.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      PairExplanation e = explain(i, j);
      if (e.trace.route == route) return e;
    }
  PairExplanation none;
  none.i = -1;
  return none;
}

TEST(QuadratureRoutes, OnePairExplainedGivesItsRouteWhatEachStageFoundAndTheMatrixValue) {
  const Mesh mesh = roomWithSolidBlock();
  const FormFactorMatrix F = test::runMethod("quadrature", mesh);
  QuadratureExplainer explain(mesh, 0);
  const double tolerance = accuracyKnobOf("quadrature").defaultValue;

  const PairExplanation enclosed = firstOn(mesh, explain, QuadratureRoute::Enclosed);
  ASSERT_GE(enclosed.i, 0);
  EXPECT_EQ(enclosed.value, 0.0);
  EXPECT_NE(enclosed.text().find("route: enclosed"), std::string::npos) << enclosed.text();

  const PairExplanation far = firstOn(mesh, explain, QuadratureRoute::FarUnoccluded);
  ASSERT_GE(far.i, 0);
  EXPECT_TRUE(far.trace.shaft.empty());
  EXPECT_NEAR(far.value, F(far.i, far.j), tolerance);
  EXPECT_GT(far.value, 0);
  EXPECT_NE(far.text().find("occluders found none"), std::string::npos) << far.text();

  // An occluded pair: the block's faces found between, kept by the clipper, H over cells.
  const PairExplanation occluded = firstOn(mesh, explain, QuadratureRoute::Cells);
  ASSERT_GE(occluded.i, 0);
  EXPECT_FALSE(occluded.trace.shaft.empty());
  EXPECT_GT(occluded.trace.clippedOccluders, 0);
  EXPECT_GT(occluded.trace.cells, 0);
  EXPECT_GT(occluded.trace.hidden, 0);
  EXPECT_NEAR(occluded.value, F(occluded.i, occluded.j), tolerance);
  // Either direction: the same pair, the value by reciprocity.
  const PairExplanation back = explain(occluded.j, occluded.i);
  EXPECT_NEAR(back.value, F(occluded.j, occluded.i), tolerance);
  const std::string text = occluded.text();
  for (const char* part : {"route: cells", "occluders found", "clipped:", "cells:", "H_", "work:", "F_"})
    EXPECT_NE(text.find(part), std::string::npos) << part << " in\n" << text;
}

// A pair whose rules stop at their work bound before the tolerance says so when explained, and the pairs
// that do are those the notes count: scenes/prism-room.json, one element per polygon, where a few pairs
// beside the prism reach it.
TEST(QuadratureRoutes, PairsAtTheWorkBoundSaySoAndAreThoseTheNotesCount) {
  const Mesh mesh = buildMesh(loadScene(test::sourcePath("scenes/prism-room.json")), MeshOptions{});
  FormFactorStats stats;
  test::runMethod("quadrature", mesh, {}, &stats);
  const std::smatch counted = [&] {
    std::smatch m;
    std::regex_search(stats.notes, m, std::regex("([0-9]+) pairs reached the work bound"));
    return m;
  }();
  ASSERT_FALSE(counted.empty()) << stats.notes;
  QuadratureExplainer explain(mesh, 0);
  const int n = static_cast<int>(mesh.size());
  long atBound = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const PairExplanation e = explain(i, j);
      if (!e.trace.budgetReached) continue;
      ++atBound;
      EXPECT_NE(e.text().find("the work bound was reached"), std::string::npos) << e.text();
    }
  EXPECT_EQ(atBound, std::stol(counted[1])) << stats.notes;
}

}  // namespace
}  // namespace rt
