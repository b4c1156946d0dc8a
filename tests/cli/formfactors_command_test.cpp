// radiosity formfactors: the summary and diagnostics lines, the matrix file, and the exact method's
// tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "core/formfactor/formfactor_method.h"
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

// Whether the CLI's list of form-factor methods (the --method line of its help) names `method`.
bool methodAvailable(const std::string& method) {
  std::string help;
  runCommand(cliPath() + " formfactors --help", &help);
  const auto line = help.find("Form-factor method:");
  if (line == std::string::npos) return false;
  const std::string methods = help.substr(line, help.find('\n', line) - line);
  return methods.find(" " + method + ",") != std::string::npos ||
         methods.find(" " + method + "\n") != std::string::npos || methods.ends_with(" " + method);
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
                     " --no-subdivide --method exact --ff-tolerance 1e-10 --quiet --output " + dir + "/F.csv",
                 &log),
      0)
      << log;
  EXPECT_NEAR(entryOfTwoByTwoCsv(dir + "/F.csv", 0, 1), kParallelSquares, 1e-10 * kParallelSquares);
}

// A work budget ends an exact run that would take long with a message naming it (exit status 1), on the
// prism room whose occluded pairs take most of the work.
TEST(FormFactorsCommand, TheExactMethodsBudgetEndsTheRunWithAMessageNamingIt) {
  if (!methodAvailable("exact")) GTEST_SKIP() << "built without the exact reference";
  std::string log;
  EXPECT_EQ(runCommand(cliPath() + " formfactors " + sourcePath("scenes/prism-room.json") +
                           " --method exact --ff-budget 100000 --quiet",
                       &log),
            1)
      << log;
  EXPECT_NE(log.find("the work budget of 100000 point evaluations (--ff-budget) ran out after"),
            std::string::npos)
      << log;
}

TEST(FormFactorsCommand, ToleranceOutOfRangeIsRejectedByName) {
  std::string log;
  EXPECT_NE(runCommand(cliPath() + " formfactors " + sourcePath("scenes/parallel-squares.json") +
                           " --method exact --ff-tolerance 2",
                       &log),
            0);
  EXPECT_NE(log.find("--ff-tolerance"), std::string::npos) << log;
}

// --tolerance is the solver's everywhere else; here, where it used to be the form factors', it still sets
// --ff-tolerance and says so.
TEST(FormFactorsCommand, TheOldToleranceSpellingSetsTheFormFactorsToleranceWithANote) {
  const std::string scene = sourcePath("scenes/parallel-squares.json") + " --no-subdivide --quiet";
  std::string old, now;
  ASSERT_EQ(runCommand(cliPath() + " formfactors " + scene + " --tolerance 1e-3", &old), 0) << old;
  ASSERT_EQ(runCommand(cliPath() + " formfactors " + scene + " --ff-tolerance 1e-3", &now), 0) << now;
  EXPECT_NE(old.find("--tolerance is deprecated, use --ff-tolerance"), std::string::npos) << old;
  EXPECT_NE(old.find("absolute tolerance 0.001"), std::string::npos) << old;
  EXPECT_NE(now.find("absolute tolerance 0.001"), std::string::npos) << now;
}

// Unnamed, the method is the registry's default (quadrature) in every command that computes F.
TEST(FormFactorsCommand, TheDefaultMethodIsQuadrature) {
  EXPECT_EQ(defaultFormFactorMethod(), "quadrature");
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " formfactors " + sourcePath("scenes/cornell-box.json") +
                           " --subdivide 2 --quiet",
                       &log),
            0)
      << log;
  EXPECT_NE(log.find("\nquadrature: "), std::string::npos) << log;  // after the scene's own warning
  EXPECT_EQ(log.find("rows of F"), std::string::npos) << log;
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

// --explain I,J: one pair's route through the quadrature method and its value, without the matrix; only
// quadrature has stages to show, and the elements must be in the mesh.
TEST(FormFactorsCommand, ExplainPrintsOnePairsRouteAndValue) {
  const std::string scene = sourcePath("scenes/cornell-box.json") + " --subdivide 2 --quiet";
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " formfactors " + scene + " --explain 3,40", &log), 0) << log;
  for (const char* part : {"pair 3 -> 40", "route: ", "F_3,40 = "})
    EXPECT_NE(log.find(part), std::string::npos) << part << " in\n" << log;
  EXPECT_EQ(log.find("pairs computed"), std::string::npos) << "no matrix: " << log;
  EXPECT_NE(runCommand(cliPath() + " formfactors " + scene + " --method hemicube --explain 3,40", &log), 0);
  EXPECT_NE(log.find("--explain"), std::string::npos) << log;
  EXPECT_NE(runCommand(cliPath() + " formfactors " + scene + " --explain 3,4000", &log), 0);
  EXPECT_NE(log.find("element 4000 is not in the mesh"), std::string::npos) << log;
}

TEST(FormFactorsCommand, TheQuadratureNotesCountThePairsOnEachRoute) {
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " formfactors " + sourcePath("scenes/cornell-box.json") +
                           " --subdivide 2 --quiet",
                       &log),
            0)
      << log;
  EXPECT_NE(log.find("(routes: "), std::string::npos) << log;
  EXPECT_NE(log.find(" cells "), std::string::npos) << log;
}

}  // namespace
}  // namespace rt::test
