// Every subcommand spells a setting as the table of step keys does, with its range and its default: values
// out of range are refused with the range before any work, old spellings still work with a note, and output
// paths are checked before the computation.
#include <gtest/gtest.h>

#include <string>

#include "support/test_paths.h"

using namespace rt::test;

namespace {

std::string cli(const std::string& arguments) {
  return cliPath() + " " + arguments;
}

std::string furnace() {
  return sourcePath("scenes/furnace-cube.json");
}

}  // namespace

TEST(SettingOptions, AValueOutOfRangeIsRefusedWithTheRangeInEveryCommand) {
  for (const std::string command :
       {"solve", "figure --view matrix --output x.png", "matrix --output K.csv"}) {
    std::string log;
    const std::string sub = command.substr(0, command.find(' '));
    const std::string rest = command.size() > sub.size() ? command.substr(sub.size()) : "";
    EXPECT_NE(runCommand(cli(sub + " " + furnace() + rest + " --method hemicube --resolution 0"), &log), 0)
        << command;
    EXPECT_NE(log.find("resolution must be in [2, 4096], not 0"), std::string::npos)
        << command << ": " << log;
  }
}

TEST(SettingOptions, MethodIsTheFormFactorMethodAndSolverTheSolverEverywhere) {
  std::string log;
  ASSERT_EQ(runCommand(cli("solve " + furnace() +
                           " --subdivide 2 --method hemicube --resolution 16 --solver jacobi"),
                       &log),
            0)
      << log;
  EXPECT_NE(log.find("hemicube: "), std::string::npos) << log;
  EXPECT_NE(log.find("solve (jacobi)"), std::string::npos) << log;
  EXPECT_EQ(log.find("deprecated"), std::string::npos) << log;
  EXPECT_NE(runCommand(cli("solve " + furnace() + " --solver guess"), &log), 0);
  EXPECT_NE(log.find("unknown solver 'guess' (known: direct, jacobi, gauss-seidel"), std::string::npos)
      << log;
}

TEST(SettingOptions, OldSpellingsStillWorkWithANote) {
  std::string log;
  ASSERT_EQ(
      runCommand(cli("solve " + furnace() + " --subdivide 2 --method gauss-seidel --formfactors analytic " +
                     "--max-iterations 50 --tonemap linear"),
                 &log),
      0)
      << log;
  EXPECT_NE(log.find("use --solver gauss-seidel"), std::string::npos) << log;
  EXPECT_NE(log.find("--formfactors is deprecated, use --method"), std::string::npos) << log;
  EXPECT_NE(log.find("--max-iterations is deprecated, use --iterations"), std::string::npos) << log;
  EXPECT_NE(log.find("--tonemap is deprecated, use --tone-map"), std::string::npos) << log;
  EXPECT_NE(log.find("solve (gauss-seidel)"), std::string::npos) << log;
  const std::string out = scratchDir("setting-options") + "/K.csv";
  ASSERT_EQ(runCommand(cli("matrix " + furnace() + " --no-subdivide --channel 1 --output " + out), &log), 0)
      << log;
  EXPECT_NE(log.find("--channel 1 is deprecated, use r, g or b"), std::string::npos) << log;
}

// One default form-factor method (the registry's: quadrature, which handles occluders), and one spelling of
// its accuracy knob, in every command that computes F.
TEST(SettingOptions, TheDefaultFormFactorMethodAndItsToleranceAreTheSameInEveryCommand) {
  for (const std::string command : {"solve", "matrix", "figure", "formfactors"}) {
    std::string help;
    runCommand(cli(command + " --help"), &help);
    EXPECT_NE(help.find("--method TEXT=quadrature"), std::string::npos) << command << ":\n" << help;
    EXPECT_NE(help.find("--ff-tolerance FLOAT=0"), std::string::npos) << command << ":\n" << help;
  }
}

TEST(SettingOptions, AnUnwritableOutputFailsBeforeTheComputation) {
  std::string log;
  EXPECT_NE(runCommand(cli("solve " + furnace() + " --subdivide 2 --image /nonexistent/dir/x.png"), &log), 0);
  EXPECT_NE(log.find("/nonexistent/dir/x.png"), std::string::npos) << log;
  EXPECT_NE(log.find("does not exist"), std::string::npos) << log;
  EXPECT_EQ(log.find("solve ("), std::string::npos) << log;  // nothing was computed
}
