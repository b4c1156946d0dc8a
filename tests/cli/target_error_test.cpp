// radiosity irradiance --target-error: the point query picks its mesh and gather rays from its own error
// estimates, and the estimate it writes beside each value (H_r_estimate...: two standard errors plus the
// mesh error) covers the error measured against the stored path-traced reference (tests/data/pathtrace) at
// 90 % of the values or more, on the closed box with the light 1 cm below an uncut ceiling.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/test_paths.h"

namespace rt::test {
namespace {

TEST(TargetError, TheQueryMeetsItsTargetAndItsEstimateCoversTheError) {
  const std::string dir = scratchDir("target-error");
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " irradiance " + sourcePath("scenes/cornell-box-closed-light-1cm.json") +
                           " --points " + dataPath("pathtrace/cornell-closed-floor-points-82.csv") +
                           " --target-error 0.5% --output " + dir + "/H.csv",
                       &log),
            0)
      << log;
  EXPECT_NE(log.find("target error 0.5 % RMS:"), std::string::npos) << log;
  const auto a = readCsv(dir + "/H.csv");
  const auto b = readCsv(dataPath("pathtrace/cornell-closed-light-1cm-floor-reference-82.csv"));
  ASSERT_EQ(a.size(), 83u);
  ASSERT_EQ(b.size(), 83u);
  int values = 0, covered = 0;
  double squares = 0, estimated = 0;
  for (const char* channel : {"r", "g", "b"}) {
    const std::string H = std::string("H_") + channel;
    const int value = column(a[0], H), estimate = column(a[0], H + "_estimate"), reference = column(b[0], H);
    for (std::size_t r = 1; r < a.size(); ++r) {
      const double truth = std::stod(b[r][static_cast<std::size_t>(reference)]);
      const double error = std::abs(std::stod(a[r][static_cast<std::size_t>(value)]) - truth);
      const double bound = std::stod(a[r][static_cast<std::size_t>(estimate)]);
      ++values;
      covered += error <= bound;
      squares += std::pow(error / truth, 2);
      estimated += std::pow(bound / truth, 2);
    }
  }
  const double rms = std::sqrt(squares / values);
  EXPECT_LE(rms, 0.005) << "the target";
  EXPECT_GE(covered, 0.9 * values) << covered << " of " << values;
  // The estimate is an honest bound, not one so wide that it says nothing: its RMS within three times the
  // error's.
  EXPECT_LT(std::sqrt(estimated / values), 3 * rms);
}

TEST(TargetError, ATargetThatIsNoFractionIsACommandLineError) {
  const std::string dir = scratchDir("target-error-bad");
  std::string log;
  EXPECT_EQ(runCommand(cliPath() + " irradiance " + sourcePath("scenes/cornell-box-closed-light-1cm.json") +
                           " --points " + dataPath("pathtrace/cornell-closed-floor-points-82.csv") +
                           " --target-error 150% --output " + dir + "/H.csv",
                       &log),
            2)
      << log;
  EXPECT_NE(log.find("0.5% or 0.005"), std::string::npos) << log;
}

}  // namespace
}  // namespace rt::test
