// Every polygonal case of tests/data/refdata/formfactors.json against the exact reference: unoccluded pairs
// to 1e-9 relative, occluded ones to 1e-7, differential-area cases through Lambert's formula. Disk cases are
// analytic-only.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "exact/exact_reference.h"
#include "exact/exact_scenes.h"
#include "support/test_paths.h"

namespace rt::exact {
namespace {

using nlohmann::json;

Vec3 toVec(const json& v) {
  return Vec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
}
Polygon toPolygon(const json& p) {
  Polygon polygon;
  for (const json& v : p["vertices"]) polygon.push_back(toVec(v));
  return polygon;
}

json loadCases() {
  std::ifstream in(rt::test::dataPath("refdata/formfactors.json"));
  return json::parse(in)["cases"];
}

const json* findCase(const json& cases, const std::string& id) {
  for (const json& c : cases)
    if (c["id"] == id) return &c;
  return nullptr;
}

class RefdataTest : public ::testing::Test {
 protected:
  void SetUp() override { cases_ = loadCases(); }
  json cases_;
};

TEST_F(RefdataTest, EveryPolygonPairToTolerance) {
  int checked = 0;
  for (const json& c : cases_) {
    const std::string type = c["geometry"]["type"];
    if (type != "polygon_to_polygon" && type != "polygon_to_polygon_with_occluders") continue;
    const json& g = c["geometry"];
    std::vector<Polygon> polygons{toPolygon(g["source"]), toPolygon(g["receiver"])};
    const bool occluded = g.contains("occluders");
    if (occluded)
      for (const json& o : g["occluders"]) polygons.push_back(toPolygon(o));
    const Mesh mesh = test::meshFromPolygons(polygons);
    const ExactOptions options;
    const EntryResult forward = elementFormFactor(mesh, 0, 1, options);
    const double expected = c["value"];
    const double tolerance = occluded ? 1e-7 : 1e-9;
    EXPECT_NEAR(forward.value, expected, tolerance * expected) << c["id"];
    EXPECT_EQ(forward.occluded, occluded) << c["id"];
    EXPECT_LE(forward.errorEstimate, tolerance * expected) << c["id"];
    if (c.contains("reciprocal_value")) {
      const EntryResult backward = elementFormFactor(mesh, 1, 0, options);
      const double reciprocal = c["reciprocal_value"];
      EXPECT_NEAR(backward.value, reciprocal, tolerance * reciprocal) << c["id"] << " (reciprocal)";
    }
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

TEST_F(RefdataTest, StraddlingReceiverNeedsHorizonClipping) {
  const json* c = findCase(cases_, "tri_straddle_requires_clipping");
  ASSERT_NE(c, nullptr);
  const Mesh mesh = test::meshFromPolygons(
      {toPolygon((*c)["geometry"]["source"]), toPolygon((*c)["geometry"]["receiver"])});
  const double value = elementFormFactor(mesh, 0, 1).value;
  EXPECT_NEAR(value, (*c)["value"].get<double>(), 1e-9 * value);
  // The unclipped (signed-kernel) value is a different number: the clipping is what makes the match.
  EXPECT_GT(std::abs(value - (*c)["value_without_horizon_clipping"].get<double>()), 1e-4);
}

TEST_F(RefdataTest, DifferentialAreaCasesByLambert) {
  int checked = 0;
  for (const json& c : cases_) {
    if (c["geometry"]["type"] != "differential_to_polygon") continue;
    const json& g = c["geometry"];
    const double value = pointToPolygonFormFactorClipped(
        toVec(g["source"]["point"]), toVec(g["source"]["normal"]), toPolygon(g["receiver"]));
    const double expected = c["value"];
    EXPECT_NEAR(value, expected, 1e-13 * expected) << c["id"];
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST_F(RefdataTest, UnitCubeEnclosureMatrix) {
  const json* c = findCase(cases_, "enclosure_unit_cube");
  ASSERT_NE(c, nullptr);
  std::vector<Polygon> faces;
  for (const json& name : (*c)["face_order"])
    faces.push_back(toPolygon((*c)["geometry"]["faces"][name.get<std::string>()]));
  const Mesh mesh = test::meshFromPolygons(faces);
  const ExactMatrix result = exactFormFactors(mesh, ExactOptions{}, noProgress());
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      const double expected = (*c)["F_matrix"][i][j];
      EXPECT_NEAR(result.F(i, j), expected, 1e-9 * std::max(expected, 1e-3)) << i << "," << j;
    }
    EXPECT_NEAR(result.F.row(i).sum(), 1.0, 1e-9);
  }
}

}  // namespace
}  // namespace rt::exact
