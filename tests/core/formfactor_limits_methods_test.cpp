// The scenes that crossed the old silent limits (occluders of 3 to 200 corners, a two-sided disc, a hundred
// occluders, the prism room), run through every registered method other than quadrature (whose own test is
// formfactor_quadrature_limits_test.cpp): the light-to-floor entry, whose occluders hide a good part, within
// the bound each method states for one entry, against the independent reference of occluder_room.h. A
// method that ignores occluders must say so in a warning instead.
//
// The bounds per entry, as the methods state them: ray casting at 256 sample pairs (raycast, hybrid)
// 0.8 % relative RMS, five times that here; montecarlo its binomial noise sqrt(F (1 - F) / N), five sigma;
// the hemicube its centroid rule (the light's centre for the whole light, a percent of F at this distance)
// plus its pixels; analytic-visibility the bias of weighting the hidden part by area, which
// docs/formfactors.md states (13 % of F for a plate half-way between two squares; 15 % here).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/formfactor/formfactor_method.h"
#include "occluder_room.h"

namespace rt {
namespace {

struct Bound {
  double relative = 0;
  FormFactorOptions run;
  bool binomial = false;  // montecarlo: sqrt(F (1 - F) / samples), five times
  bool ignoresOccluders = false;
};

Bound boundOf(const std::string& method) {
  Bound b;
  if (method == "raycast" || method == "hybrid") {
    b.run.samples = 256, b.relative = 0.04;
  } else if (method == "montecarlo") {
    b.run.samples = 30000, b.binomial = true;
  } else if (method == "hemicube") {
    b.run.hemicubeResolution = 512, b.relative = 0.02;
  } else if (method == "analytic-visibility") {
    b.run.samples = 256, b.relative = 0.15;
  } else if (method == "analytic" || method == "nusselt") {
    b.ignoresOccluders = true;
  }
  return b;
}

struct Case {
  std::string name;
  Scene scene;
  std::vector<Polygon> bodies;
};

std::vector<Case> limitCases() {
  std::vector<Case> cases;
  for (int n : {3, 8, 29, 64, 200}) {
    Case prism{std::to_string(n) + "-sided prism", test::litRoom(), {}};
    prism.bodies.push_back(test::addPrism(prism.scene, n, 0.5, 0.5, 0.15, 0.0, 0.3));
    cases.push_back(std::move(prism));
    Case disc{std::to_string(n) + "-sided two-sided disc", test::litRoom(), {}};
    disc.bodies.push_back(test::addDisc(disc.scene, n, 0.5, 0.5, 0.12, 0.5));
    cases.push_back(std::move(disc));
  }
  Case hundred{"a hundred prisms", test::litRoom(), {}};
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      hundred.bodies.push_back(
          test::addPrism(hundred.scene, 6, 0.095 + 0.09 * i, 0.095 + 0.09 * j, 0.015, 0.02, 0.05));
  cases.push_back(std::move(hundred));
  Case room{"prism room (40 and 36 sides)", test::litRoom(), {}};
  room.bodies.push_back(test::addPrism(room.scene, 40, 0.3, 0.3, 0.12, 0.0, 0.3));
  room.bodies.push_back(test::addDisc(room.scene, 36, 0.68, 0.68, 0.08, 0.4));
  cases.push_back(std::move(room));
  return cases;
}

class FormerLimits : public ::testing::TestWithParam<std::string> {};

TEST_P(FormerLimits, LightToFloorWithinTheMethodsBound) {
  const std::string method = GetParam();
  if (method == "quadrature") GTEST_SKIP() << "formfactor_quadrature_limits_test.cpp";
  const Bound bound = boundOf(method);
  for (const Case& c : limitCases()) {
    const Mesh mesh = buildMesh(c.scene, MeshOptions{});
    const int light = test::elementsOf(mesh, test::kLightPatch).front(),
              floor = test::elementsOf(mesh, test::kFloorPatch).front();
    const double expected =
        test::referenceLightToFloor(mesh.polygon(light), mesh.polygon(floor), c.bodies, 16);
    FormFactorStats stats;
    const FormFactorMatrix F = test::runMethod(method, mesh, bound.run, &stats);
    if (bound.ignoresOccluders) {
      EXPECT_FALSE(stats.warnings.empty()) << method << " ignores occluders without a word: " << c.name;
      continue;
    }
    const double allowed =
        bound.binomial ? 5 * std::sqrt(expected * (1 - expected) / static_cast<double>(bound.run.samples))
                       : bound.relative * expected;
    std::printf("%s, %s: %.5f, reference %.5f (allowed %.1e)\n", method.c_str(), c.name.c_str(),
                F(light, floor), expected, allowed);
    EXPECT_NEAR(F(light, floor), expected, allowed) << method << ", " << c.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Registered, FormerLimits, ::testing::ValuesIn(formFactorMethodNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return test::testNameOf(info.param);
                         });

}  // namespace
}  // namespace rt
