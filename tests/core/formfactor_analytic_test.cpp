// The analytic form factors against the public reference values (tests/data/refdata/formfactors.json, 1e-9
// relative) and against closed forms and identities for the hard cases (shared edges, slivers, near contact).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/formfactor/analytic.h"
#include "core/polygon.h"
#include "support/test_paths.h"

namespace rt {
namespace {

using nlohmann::json;

Vec3 vec(const json& a) {
  return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()};
}
Polygon polygonOf(const json& p) {
  Polygon out;
  for (const json& v : p["vertices"]) out.push_back(vec(v));
  return out;
}

json loadReference() {
  std::ifstream in(test::dataPath("refdata/formfactors.json"));
  return json::parse(in);
}

// Howell C-11: identical parallel directly opposed rectangles a x b at distance c.
double parallelRectangles(double a, double b, double c) {
  const double x = a / c, y = b / c;
  const double x1 = std::sqrt(1 + x * x), y1 = std::sqrt(1 + y * y);
  return 2 / (std::numbers::pi * x * y) *
         (std::log(x1 * y1 / std::sqrt(1 + x * x + y * y)) + x * y1 * std::atan(x / y1) +
          y * x1 * std::atan(y / x1) - x * std::atan(x) - y * std::atan(y));
}

TEST(AnalyticFormFactor, FarApartPairsKeepTheirDigitsInAnyUnit) {
  // Squares 1 cm wide, 5 cm to 10 m apart, in metres and in millimetres: the double contour integral of ln r
  // cancels (distance / size)^2 of its digits; far pairs take Lambert's formula over the source instead.
  // References: Howell C-11 evaluated with 50 digits (the closed form cancels too many in double).
  const std::vector<std::pair<double, double>> cases{{0.05, 0.012403977313245101},
                                                     {0.1, 0.0031620568387576013},
                                                     {1.0, 3.1828866732829196e-5},
                                                     {10.0, 3.1830967397738026e-7}};
  for (double unit : {1.0, 1000.0})
    for (const auto& [distance, reference] : cases) {
      const double a = 0.01 * unit, d = distance * unit;
      const Polygon from{{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0}};
      const Polygon to{{0, 0, d}, {0, a, d}, {a, a, d}, {a, 0, d}};
      const double tolerance = 1e-11 * reference;
      EXPECT_NEAR(polygonToPolygonFormFactor(from, to), reference, tolerance) << unit << " " << distance;
      EXPECT_NEAR(polygonToPolygonFormFactor(to, from), reference, tolerance) << unit << " " << distance;
    }
}

TEST(AnalyticFormFactor, MatchesEveryUnoccludedReferenceCase) {
  const json reference = loadReference();
  int checked = 0;
  for (const json& c : reference["cases"]) {
    const std::string type = c["geometry"]["type"];
    const json& g = c["geometry"];
    SCOPED_TRACE(c["id"].get<std::string>());
    if (type == "polygon_to_polygon") {
      const Polygon from = polygonOf(g["source"]), to = polygonOf(g["receiver"]);
      const double value = c["value"];
      EXPECT_NEAR(polygonToPolygonFormFactor(from, to), value, 1e-9 * value);
      if (c.contains("reciprocal_value")) {
        const double back = c["reciprocal_value"];
        EXPECT_NEAR(polygonToPolygonFormFactor(to, from), back, 1e-9 * back);
      }
      ++checked;
    } else if (type == "differential_to_polygon") {
      const double value = c["value"];
      EXPECT_NEAR(pointToPolygonFormFactor(vec(g["source"]["point"]), vec(g["source"]["normal"]),
                                           polygonOf(g["receiver"])),
                  value, 1e-9 * value);
      ++checked;
    } else if (type == "enclosure") {
      std::vector<Polygon> faces;
      for (const json& name : c["face_order"])
        faces.push_back(polygonOf(g["faces"][name.get<std::string>()]));
      for (std::size_t i = 0; i < faces.size(); ++i) {
        double sum = 0;
        for (std::size_t j = 0; j < faces.size(); ++j) {
          const double expected = c["F_matrix"][i][j];
          const double value = polygonToPolygonFormFactor(faces[i], faces[j]);
          EXPECT_NEAR(value, expected, 1e-9 * expected) << i << " -> " << j;
          sum += value;
        }
        EXPECT_NEAR(sum, 1.0, 1e-9);
      }
      ++checked;
    }
    // disk_to_disk (not a polygon) and occluded cases (need visibility) belong to other tests.
  }
  EXPECT_GE(checked, 12);
}

// Source: unit square in z = 0 facing +z; receiver: unit square hinged on the y axis at an included angle
// (degrees).
double hingedSquares(double includedDegrees) {
  const double a = (180.0 - includedDegrees) * std::numbers::pi / 180.0;
  const Vec3 d(-std::cos(a), 0, std::sin(a));
  const Polygon source = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const Polygon receiver = {{0, 0, 0}, {0, 1, 0}, Vec3(0, 1, 0) + d, d};
  return polygonToPolygonFormFactor(source, receiver);
}

// Reference values computed independently with mpmath (25 digits): the outer integral of Lambert's point
// formula over the source by tanh-sinh quadrature (which handles the logarithmic behaviour at a shared edge).
TEST(AnalyticFormFactor, HingedSquaresAtAnyAngle) {
  const std::pair<double, double> cases[] = {{150, 0.021345325412689370445}, {120, 0.086615001118276058831},
                                             {90, 0.20004377607540315424},   {60, 0.3709053211500514359},
                                             {30, 0.6190283230908032534},    {10, 0.84960612496284717064}};
  for (const auto& [angle, reference] : cases)
    EXPECT_NEAR(hingedSquares(angle), reference, 1e-9 * reference) << angle;
  // Closing the hinge: 180 degrees is coplanar (nothing exchanged), 0 degrees is face to face.
  EXPECT_EQ(hingedSquares(180), 0.0);
}

TEST(AnalyticFormFactor, AlmostCollinearSharedEdgesEndQuickly) {
  // Meshing in millimetres rounds a shared edge's ends differently on its two sides, so two edges that should
  // be collinear meet at an angle of 1e-12 to 1e-9 rad. The integration used to bisect the whole overlap down
  // to 1e-15 of its length (2^50 panels: a hang); it now grades towards the ends only. The value moves by
  // about the size of the perturbation.
  for (double tilt : {1e-12, 1e-10, 1e-8}) {
    const Polygon source = {{0, 0, 0}, {40, 0, 0}, {40, 40, 0}, {0, 40, 0}};
    const Polygon receiver = {{tilt, 0, 0}, {0, 40, 0}, {0, 40, 40}, {0, 0, 40}};
    EXPECT_NEAR(polygonToPolygonFormFactor(source, receiver), 0.20004377607540315424, 1e-7) << tilt;
  }
}

TEST(AnalyticFormFactor, SliverTriangleStandingOnASharedEdge) {
  // A 1000:1 triangle standing on the square's edge: its long edges meet the shared edge at 1/500 rad.
  const Polygon square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const Polygon sliver = {{0, 0, 0}, {0, 1, 0}, {0, 0.5, 0.001}};
  const double reference = 0.00024985285167783718593;  // mpmath, as above, x split at 1e-4, 1e-3, 1e-2, 0.1
  EXPECT_NEAR(polygonToPolygonFormFactor(square, sliver), reference, 1e-9 * reference);
  EXPECT_NEAR(polygonToPolygonFormFactor(sliver, square) * polygonArea(sliver), reference, 1e-9 * reference);
}

TEST(AnalyticFormFactor, TrianglesSharingOnlyAVertex) {
  const Polygon source = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Polygon receiver = {{0, 0, 0}, {-0.4, 0.5, 0.6}, {0.3, -0.2, 0.9}};
  const double reference = 0.10925053018902142514;  // mpmath, as above
  EXPECT_NEAR(polygonToPolygonFormFactor(source, receiver), reference, 1e-9 * reference);
}

TEST(AnalyticFormFactor, SliversAndNearContactMatchClosedForms) {
  auto opposed = [](double a, double b, double c) {
    const Polygon source = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}};
    const Polygon receiver = {{0, 0, c}, {0, b, c}, {a, b, c}, {a, 0, c}};
    return polygonToPolygonFormFactor(source, receiver);
  };
  // Howell C-11 evaluated with mpmath at 25 digits (the double-precision formula cancels badly at these
  // ratios).
  EXPECT_NEAR(opposed(1, 1, 1e-6), 0.99999800001002952124, 1e-9);
  EXPECT_NEAR(opposed(1, 0.001, 1), 0.00024999992423712993598, 1e-9 * 0.00024999992423712993598);
  EXPECT_NEAR(opposed(1, 0.001, 0.001), 0.41393419807935092152, 1e-9 * 0.41393419807935092152);
  // Where the double formula is well conditioned the two agree.
  EXPECT_NEAR(opposed(2, 3, 1.5), parallelRectangles(2, 3, 1.5), 1e-12);
}

TEST(AnalyticFormFactor, ReciprocityHoldsForEveryOrientation) {
  const Polygon a = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Polygon b = {{0.2, 0.1, 1.0}, {0.1, 0.9, 0.7}, {1.1, 0.3, 0.8}};
  EXPECT_NEAR(polygonArea(a) * polygonToPolygonFormFactor(a, b),
              polygonArea(b) * polygonToPolygonFormFactor(b, a), 1e-14);
}

TEST(AnalyticFormFactor, BackFacingAndCoplanarGiveZero) {
  const Polygon floor = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const Polygon upward = {
      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};  // faces +z: its back is towards the floor
  EXPECT_EQ(polygonToPolygonFormFactor(floor, upward), 0.0);
  const Polygon beside = {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}};
  EXPECT_EQ(polygonToPolygonFormFactor(floor, beside), 0.0);
  EXPECT_EQ(pointToPolygonFormFactor(Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 1), upward), 0.0);  // behind it
}

TEST(AnalyticFormFactor, ClippingKeepsOnlyTheFrontPart) {
  const Polygon square = {{-1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 1, 0}};
  const Polygon half = clipPolygonToPlane(square, Vec3::Zero(), Vec3(1, 0, 0));
  EXPECT_NEAR(polygonArea(half), 1.0, 1e-15);
  EXPECT_TRUE(clipPolygonToPlane(square, Vec3(2, 0, 0), Vec3(1, 0, 0)).empty());
  EXPECT_EQ(clipPolygonToPlane(square, Vec3(-2, 0, 0), Vec3(1, 0, 0)).size(), 4u);
}

TEST(AnalyticFormFactor, PointFormulaIntegratesToThePolygonFormula) {
  // The area average of Lambert's point formula over the source is F_ij: 64 x 64 Gauss points on a
  // well-separated pair agree to far below 1e-9.
  const Polygon source = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const Polygon receiver = {{0.5, 0, 2}, {0.5, 1, 2}, {1.5, 1, 2.5}, {1.5, 0, 2.5}};
  double sum = 0;
  const int n = 24;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      sum += pointToPolygonFormFactor(Vec3((a + 0.5) / n, (b + 0.5) / n, 0), Vec3(0, 0, 1), receiver);
  EXPECT_NEAR(sum / (n * n), polygonToPolygonFormFactor(source, receiver), 1e-5);
}

}  // namespace
}  // namespace rt
