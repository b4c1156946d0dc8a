// `radiosity solve --basis linear`: the furnace cube with linear elements, the reports on stderr, the image
// drawn from the corners, and the clear refusal of a solver or method the basis cannot use.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/test_paths.h"

namespace rt::test {
namespace {

TEST(SolveBasisCommand, LinearFurnaceCubeGivesEOverOneMinusRho) {
  const std::string out = scratchDir("solve-linear-furnace") + "/B.csv";
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " solve " + sourcePath("scenes/furnace-cube.json") +
                           " --subdivide 2 --basis linear --solver direct --output " + out,
                       &log),
            0)
      << log;
  EXPECT_NE(log.find("linear basis, 54 nodes"), std::string::npos) << log;  // 3 x 3 per face
  const auto rows = readCsv(out);
  ASSERT_EQ(rows.size(), 1u + 6u * 4u);
  for (std::size_t r = 1; r < rows.size(); ++r)
    for (int c = 4; c < 7; ++c) EXPECT_NEAR(std::stod(rows[r][c]), 2.0, 1e-9) << "row " << r;
}

TEST(SolveBasisCommand, RefusesSolversAndMethodsTheBasisCannotUse) {
  const std::string scene = sourcePath("scenes/parallel-squares.json");
  std::string log;
  EXPECT_NE(
      runCommand(cliPath() + " solve " + scene + " --subdivide 2 --basis linear --solver local-lines", &log),
      0);
  EXPECT_NE(log.find("one value per element"), std::string::npos) << log;
  EXPECT_NE(
      runCommand(cliPath() + " solve " + scene + " --subdivide 2 --basis linear --solver random-walk", &log),
      0);
  EXPECT_NE(log.find("reciprocity"), std::string::npos) << log;
  EXPECT_NE(
      runCommand(cliPath() + " solve " + scene + " --subdivide 2 --basis linear --method hemicube", &log), 0);
  EXPECT_NE(log.find("does not apply"), std::string::npos) << log;
  EXPECT_NE(runCommand(cliPath() + " solve " + scene + " --basis cubic", &log), 0);
}

#ifdef RT_HAVE_VIZ
TEST(SolveBasisCommand, ImageOfTheLinearSolution) {
  const std::string png = scratchDir("solve-linear-image") + "/linear.png";
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " solve " + sourcePath("scenes/cornell-box.json") +
                           " --subdivide 3 --basis linear --width 64 --height 64 --image " + png,
                       &log),
            0)
      << log;
  EXPECT_TRUE(std::filesystem::exists(png));
}
#endif

}  // namespace
}  // namespace rt::test
