// radiosity compare-pt: the radiosity image and the two-pass image of the closed Cornell box against the path
// tracer's. The two-pass picture has no mesh artefacts, so it must be the closer of the two.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "support/test_paths.h"

namespace rt::test {
namespace {

// The row of the printed table that starts with `name`, as numbers.
std::vector<double> tableRow(const std::string& log, const std::string& name) {
  std::stringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(name + ",", 0) != 0) continue;
    std::vector<double> values;
    std::stringstream cells(line.substr(name.size() + 1));
    std::string cell;
    while (std::getline(cells, cell, ',')) values.push_back(std::stod(cell));
    return values;
  }
  return {};
}

TEST(ComparePtCommand, TwoPassIsCloserToThePathTracerThanTheRadiosityImage) {
  const std::string dir = scratchDir("compare-pt");
  std::string log;
  ASSERT_EQ(
      runCommand(cliPath() + " compare-pt " + sourcePath("scenes/cornell-box-closed.json") +
                     " --max-edge 100 --width 40 --height 40 --paths 256 --gather-rays 1024 --output " + dir,
                 &log),
      0)
      << log;
  const auto radiosity = tableRow(log, "radiosity"), twoPass = tableRow(log, "two-pass");
  ASSERT_EQ(radiosity.size(), 5u) << log;
  ASSERT_EQ(twoPass.size(), 5u) << log;
  // error within its interval, the interval ordered
  for (const auto& row : {radiosity, twoPass}) {
    EXPECT_LE(row[3], row[2]);
    EXPECT_LE(row[2], row[4]);
  }
  // The reference's noise is part of each difference: below the radiosity image's; the two-pass picture's own
  // error is so small that its difference is the noise alone, give or take the sampling of 1,600 pixels.
  EXPECT_LT(radiosity[1], radiosity[0]);
  EXPECT_NEAR(twoPass[0] / twoPass[1], 1.0, 0.15) << log;
  EXPECT_LT(twoPass[2], radiosity[2]) << log;
  for (const char* file : {"path-traced.pfm", "path-traced.ppm", "radiosity.pfm", "two-pass.pfm",
                           "error-radiosity.ppm", "error-two-pass.ppm", "path-traced-error.pfm"})
    EXPECT_TRUE(std::filesystem::is_regular_file(dir + "/" + file)) << file;
}

}  // namespace
}  // namespace rt::test
