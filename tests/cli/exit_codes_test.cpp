// One exit code per class of error, the same in every subcommand (src/cli/cli_common.h, docs/robustness.md):
// 2 command line, 3 input (file, line or value), and the message names the file.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/test_paths.h"

namespace rt::test {
namespace {

constexpr int kUsage = 2, kInput = 3;

std::string scratchScene(const std::string& name, const std::string& text) {
  const std::string path = scratchDir("exit-codes") + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(ExitCodes, MissingSceneIsAnInputErrorInEverySubcommand) {
  for (const char* command : {"solve", "formfactors", "matrix", "figure"}) {
    std::string log;
    EXPECT_EQ(runCommand(cliPath() + " " + std::string(command) + " /nonexistent/room.json", &log), kInput)
        << command << log;
    EXPECT_NE(log.find("/nonexistent/room.json: error: cannot open the file"), std::string::npos)
        << command << log;
  }
}

TEST(ExitCodes, CommandLineMistakesAreUsageErrors) {
  const std::string scene = sourcePath("scenes/parallel-squares.json");
  std::string log;
  EXPECT_EQ(runCommand(cliPath() + " solve " + scene + " --no-such-option", &log), kUsage) << log;
  EXPECT_EQ(runCommand(cliPath() + " formfactors " + scene + " --method no-such-method", &log), kUsage)
      << log;
  EXPECT_EQ(runCommand(cliPath() + " no-such-command", &log), kUsage) << log;
  EXPECT_EQ(runCommand(cliPath() + " --help", &log), 0) << log;
  EXPECT_NE(log.find("Exit status: 0 success"), std::string::npos) << log;
}

TEST(ExitCodes, BadSceneIsAnInputErrorWithTheLine) {
  const std::string path = scratchScene("bad.obj", "v 0 0 0\nv 1 0 0\nv 1 nan 0\nf 1 2 3\n");
  for (const std::string& command :
       {std::string("solve"), std::string("formfactors"), "matrix --output " + path + ".csv"}) {
    std::string log;
    EXPECT_EQ(runCommand(cliPath() + " " + command + " " + path, &log), kInput) << command << log;
    EXPECT_NE(log.find("bad.obj:3: error: vertex coordinate 'nan' is not a finite number"), std::string::npos)
        << command << log;
  }
}

TEST(ExitCodes, AbsurdMeshIsRefusedWithTheNumbersNotAnAllocationFailure) {
  std::string log;
  EXPECT_EQ(
      runCommand(cliPath() + " solve " + sourcePath("scenes/cornell-box.json") + " --max-edge 0.001", &log),
      kInput)
      << log;
  EXPECT_NE(log.find("--max-edge 0.001 would make about"), std::string::npos) << log;
  EXPECT_EQ(log.find("bad_alloc"), std::string::npos) << log;
}

TEST(ExitCodes, LightFacingAwayIsReportedByTheSolve) {
  // One light square facing away (-z) from a receiver above it (facing -z, towards the light's back).
  const std::string path = scratchScene("away.json", R"({
  "materials": [{"name": "light", "reflectance": [0, 0, 0], "emission": [1, 1, 1]},
                {"name": "white", "reflectance": [0.5, 0.5, 0.5]}],
  "surfaces": [
    {"name": "lamp", "material": "light", "polygons": [[[0, 0, 0], [0, 1, 0], [1, 1, 0], [1, 0, 0]]]},
    {"name": "ceiling", "material": "white", "polygons": [[[0, 0, 1], [0, 1, 1], [1, 1, 1], [1, 0, 1]]]}]
})");
  std::string log;
  EXPECT_EQ(runCommand(cliPath() + " solve " + path + " --no-subdivide", &log), 0) << log;
  EXPECT_NE(log.find("away.json:5 at /surfaces/0/polygons/0: warning: light 'lamp' faces away"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("warning: no light reaches any surface"), std::string::npos) << log;
}

TEST(ExitCodes, FormFactorsNeedNoLightButASolveDoes) {
  // Two parallel squares, neither emitting: F is pure geometry, so formfactors and matrix --what F work;
  // solve and the radiosity view refuse, naming the file.
  const std::string path = scratchScene("dark.json", R"({
  "materials": [{"name": "white", "reflectance": [0.5, 0.5, 0.5]}],
  "surfaces": [
    {"name": "lower", "material": "white", "polygons": [[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]]},
    {"name": "upper", "material": "white", "polygons": [[[0, 0, 1], [0, 1, 1], [1, 1, 1], [1, 0, 1]]]}]
})");
  std::string log;
  EXPECT_EQ(runCommand(cliPath() + " formfactors " + path + " --no-subdivide --quiet", &log), 0) << log;
  EXPECT_NE(log.find("2 elements"), std::string::npos) << log;
  EXPECT_EQ(
      runCommand(cliPath() + " matrix " + path + " --no-subdivide --what F --output " + path + ".csv", &log),
      0)
      << log;
  EXPECT_EQ(runCommand(cliPath() + " solve " + path + " --no-subdivide", &log), kInput) << log;
  EXPECT_NE(log.find("dark.json: error: no light"), std::string::npos) << log;
}

}  // namespace
}  // namespace rt::test
