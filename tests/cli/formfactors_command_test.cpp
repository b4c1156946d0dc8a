// radiosity formfactors: the summary and diagnostics lines, the matrix file, and the exact method's
// tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "support/test_paths.h"

namespace rt::test {
namespace {

// Howell C-11: parallel unit squares at distance 1.
constexpr double kParallelSquares = 0.19982489569838738;

double entryOfTwoByTwoCsv(const std::string& path, int row, int column) {
  std::ifstream in(path);
  std::string line;
  int r = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (r++ != row) continue;
    const auto comma = line.find(',');
    return std::stod(column == 0 ? line.substr(0, comma) : line.substr(comma + 1));
  }
  return NAN;
}

// Whether the CLI was built with the named optional method. Only "exact" is optional; the help text cannot
// tell, since option descriptions name it in every build.
bool methodAvailable(const std::string& method) {
#ifdef RT_HAVE_EXACT
  return method == "exact";
#else
  return method != "exact";
#endif
}

TEST(FormFactorsCommand, PrintsSummaryAndDiagnosticsAndWritesTheMatrix) {
  const std::string out = scratchDir("formfactors-analytic") + "/F.csv";
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " formfactors " + sourcePath("scenes/parallel-squares.json") +
                           " --no-subdivide --method analytic --quiet --output " + out,
                       &log),
            0)
      << log;
  EXPECT_NE(log.find("analytic: 2 elements"), std::string::npos) << log;
  EXPECT_NE(log.find("diagnostics:"), std::string::npos) << log;
  EXPECT_NEAR(entryOfTwoByTwoCsv(out, 0, 1), kParallelSquares, 1e-12);
  EXPECT_NEAR(entryOfTwoByTwoCsv(out, 1, 0), kParallelSquares, 1e-12);
}

TEST(FormFactorsCommand, ExactMethodHonoursTheTolerance) {
  if (!methodAvailable("exact")) GTEST_SKIP() << "built without the exact reference";
  const std::string dir = scratchDir("formfactors-exact");
  std::string log;
  ASSERT_EQ(
      runCommand(cliPath() + " formfactors " + sourcePath("scenes/parallel-squares.json") +
                     " --no-subdivide --method exact --tolerance 1e-10 --quiet --output " + dir + "/F.csv",
                 &log),
      0)
      << log;
  EXPECT_NEAR(entryOfTwoByTwoCsv(dir + "/F.csv", 0, 1), kParallelSquares, 1e-10 * kParallelSquares);
}

TEST(FormFactorsCommand, ToleranceOutOfRangeIsRejectedByName) {
  std::string log;
  EXPECT_NE(runCommand(cliPath() + " formfactors " + sourcePath("scenes/parallel-squares.json") +
                           " --method exact --tolerance 0",
                       &log),
            0);
  EXPECT_NE(log.find("--tolerance"), std::string::npos) << log;
}

TEST(FormFactorsCommand, ComparesWithAReferenceMatrixSavedEarlier) {
  const std::string dir = scratchDir("formfactors-compare");
  const std::string scene = sourcePath("scenes/cornell-box.json") + " --subdivide 2 --quiet";
  std::string log;
  ASSERT_EQ(
      runCommand(cliPath() + " formfactors " + scene + " --method analytic --output " + dir + "/A.npy", &log),
      0)
      << log;
  // Against itself: no error at all.
  ASSERT_EQ(
      runCommand(cliPath() + " formfactors " + scene + " --method analytic --compare-to " + dir + "/A.npy",
                 &log),
      0)
      << log;
  EXPECT_NE(log.find("rms error 0.000e+00, relative rms 0 %, max error 0.000e+00"), std::string::npos) << log;
  // The hemicube sees the blocks, the unoccluded analytic does not: a visible difference.
  ASSERT_EQ(
      runCommand(cliPath() + " formfactors " + scene + " --method hemicube --compare-to " + dir + "/A.npy",
                 &log),
      0)
      << log;
  EXPECT_NE(log.find("against " + dir + "/A.npy: rms error "), std::string::npos) << log;
  EXPECT_EQ(log.find("rms error 0.000e+00"), std::string::npos) << log;
}

TEST(FormFactorsCommand, AReferenceOfAnotherMeshOrNoMatrixIsAClearError) {
  const std::string dir = scratchDir("formfactors-compare-errors");
  const std::string scene = sourcePath("scenes/cornell-box.json") + " --quiet";
  std::string log;
  ASSERT_EQ(
      runCommand(cliPath() + " formfactors " + scene + " --subdivide 2 --output " + dir + "/A.npy", &log), 0)
      << log;
  EXPECT_NE(
      runCommand(cliPath() + " formfactors " + scene + " --subdivide 3 --compare-to " + dir + "/A.npy", &log),
      0);
  EXPECT_NE(log.find("A.npy: error: the reference is 80 x 80, this mesh has 180 elements"), std::string::npos)
      << log;
  std::ofstream(dir + "/junk.npy") << "not a matrix";
  EXPECT_NE(runCommand(cliPath() + " formfactors " + scene + " --compare-to " + dir + "/junk.npy", &log), 0);
  EXPECT_NE(log.find("junk.npy: error: not a NumPy .npy file"), std::string::npos) << log;
  EXPECT_NE(runCommand(cliPath() + " formfactors " + scene + " --compare-to " + dir + "/missing.npy", &log),
            0);
  EXPECT_NE(log.find("missing.npy: error: cannot open the file"), std::string::npos) << log;
}

}  // namespace
}  // namespace rt::test
