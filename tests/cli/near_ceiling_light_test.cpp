// The closed Cornell box as people model it: the light a separate quad 0.1 mm below an uncut ceiling
// (scenes/cornell-box-closed-light-0.1mm.json). The default mesh cuts the ceiling along the light's outline
// and says so; the two-pass floor irradiance at 82 points is then close to the stored path-traced reference
// (tests/data/pathtrace/README.md), and its parts (--breakdown) add up and agree with the reference's.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/test_paths.h"

namespace rt::test {
namespace {

struct Errors {
  double rms = 0, mean = 0;  // relative to the reference's H, over points and channels
  double directRms = 0;      // of the direct part, relative to the reference's H
  int values = 0;
};

// The answer `a` against the reference `b`, both with the breakdown's columns.
Errors compare(const std::vector<std::vector<std::string>>& a,
               const std::vector<std::vector<std::string>>& b) {
  Errors e;
  for (const char* channel : {"r", "g", "b"}) {
    const std::string H = std::string("H_") + channel;
    const int value = column(a[0], H), reference = column(b[0], H);
    const int direct = column(a[0], H + "_direct"), referenceDirect = column(b[0], H + "_direct");
    for (std::size_t r = 1; r < a.size() && r < b.size(); ++r) {
      const double truth = std::stod(b[r][static_cast<std::size_t>(reference)]);
      const double relative = (std::stod(a[r][static_cast<std::size_t>(value)]) - truth) / truth;
      e.rms += relative * relative;
      e.mean += relative;
      e.directRms += std::pow((std::stod(a[r][static_cast<std::size_t>(direct)]) -
                               std::stod(b[r][static_cast<std::size_t>(referenceDirect)])) /
                                  truth,
                              2);
      ++e.values;
    }
  }
  e.rms = std::sqrt(e.rms / e.values);
  e.directRms = std::sqrt(e.directRms / e.values);
  e.mean /= e.values;
  return e;
}

TEST(NearCeilingLight, TwoPassFloorIrradianceAgainstThePathTracedReference) {
  const std::string dir = scratchDir("near-ceiling-light");
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " irradiance " + sourcePath("scenes/cornell-box-closed-light-0.1mm.json") +
                           " --points " + dataPath("pathtrace/cornell-closed-floor-points-82.csv") +
                           " --no-mesh-error --breakdown --output " + dir + "/H.csv",
                       &log),
            0)
      << log;
  // The default mesh cut the ceiling along the light's outline, and said so.
  EXPECT_NE(
      log.find("mesh: cut ceiling (patch 2) along the outline of light, 0.1 mm in front of it (overlap)"),
      std::string::npos)
      << log;
  const auto a = readCsv(dir + "/H.csv");
  const auto b = readCsv(dataPath("pathtrace/cornell-closed-light-0.1mm-floor-reference-82.csv"));
  ASSERT_EQ(a.size(), 83u);
  ASSERT_EQ(b.size(), 83u);
  // The parts add up to H.
  for (const char* channel : {"r", "g", "b"}) {
    const std::string H = std::string("H_") + channel;
    for (std::size_t r = 1; r < a.size(); ++r) {
      double sum = 0;
      for (const char* part : {"_direct", "_bounce", "_rest"})
        sum += std::stod(a[r][static_cast<std::size_t>(column(a[0], H + part))]);
      EXPECT_NEAR(sum, std::stod(a[r][static_cast<std::size_t>(column(a[0], H))]), 1e-6 * sum);
    }
  }
  const Errors e = compare(a, b);
  // The direct light is exact in the two-pass method: what is left is the reference's own noise.
  EXPECT_LT(e.directRms, 0.002);
  // The target of 0.5 % RMS, and a bias well inside the noise: without the cut along the light's outline the
  // ceiling elements half under the light bias the floor by -0.21 %.
  EXPECT_LT(e.rms, 0.005) << "mean " << e.mean;
  EXPECT_LT(std::abs(e.mean), 0.0015) << "RMS " << e.rms;
}

}  // namespace
}  // namespace rt::test
