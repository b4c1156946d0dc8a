// `radiosity solve --basis linear`: the furnace cube with linear elements, the reports on stderr, the image
// drawn from the corners, the node values as CSV and as the PLY's vertices, and the clear refusal of a
// solver or method the basis cannot use.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

// The PLY's vertices: x, y, z, B_r, B_g, B_b of each.
std::vector<std::vector<double>> plyVertices(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  long count = 0;
  while (std::getline(in, line) && line != "end_header")
    if (line.rfind("element vertex ", 0) == 0) count = std::stol(line.substr(15));
  std::vector<std::vector<double>> vertices;
  for (long k = 0; k < count && std::getline(in, line); ++k) {
    std::istringstream fields(line);
    std::vector<double> v(6);
    for (double& x : v) fields >> x;
    vertices.push_back(v);
  }
  return vertices;
}

TEST(SolveBasisCommand, NodeValuesAsCsvAndAsThePlysVertices) {
  const std::string dir = scratchDir("solve-linear-nodes");
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " solve " + sourcePath("scenes/parallel-squares.json") +
                           " --subdivide 2 --basis linear --solver direct --output " + dir +
                           "/B.csv --nodes " + dir + "/nodes.csv --ply " + dir + "/mesh.ply",
                       &log),
            0)
      << log;
  const auto nodes = readCsv(dir + "/nodes.csv");
  ASSERT_EQ(nodes.size(), 1u + 2u * 9u) << "3 x 3 nodes on each square";
  EXPECT_EQ(nodes[0][0], "node");
  EXPECT_EQ(nodes[0][4], "B_r");
  const auto elements = readCsv(dir + "/B.csv");
  // The element averages integrate the linear function: the same power per channel.
  for (int c = 0; c < 3; ++c) {
    double nodal = 0, averaged = 0;
    for (std::size_t r = 1; r < nodes.size(); ++r)
      nodal += std::stod(nodes[r][3]) * std::stod(nodes[r][4 + c]);
    for (std::size_t r = 1; r < elements.size(); ++r)
      averaged += std::stod(elements[r][3]) * std::stod(elements[r][4 + c]);
    EXPECT_NEAR(nodal, averaged, 1e-9 * std::abs(averaged)) << "channel " << c;
  }
  // Every vertex of the PLY carries the value of the node it sits on.
  const auto vertices = plyVertices(dir + "/mesh.ply");
  ASSERT_EQ(vertices.size(), 2u * 4u * 4u) << "four corners per element";
  double spread = 0;
  for (const auto& v : vertices) {
    bool found = false;
    for (std::size_t r = 1; r < nodes.size() && !found; ++r) {
      double distance = 0;
      for (int k = 0; k < 3; ++k) distance += std::abs(std::stod(nodes[r][7 + k]) - v[k]);
      if (distance > 1e-6) continue;
      found = true;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(v[3 + c], std::stod(nodes[r][4 + c]),
                    1e-6 * std::abs(std::stod(nodes[r][4 + c])) + 1e-12);
    }
    EXPECT_TRUE(found) << "a vertex at " << v[0] << " " << v[1] << " " << v[2] << " is no node";
    spread = std::max(spread, std::abs(v[3] - vertices.front()[3]));
  }
  EXPECT_GT(spread, 0) << "the linear function varies over the squares";
}

TEST(SolveBasisCommand, NodeValuesNeedTheLinearBasis) {
  std::string log;
  EXPECT_NE(runCommand(cliPath() + " solve " + sourcePath("scenes/parallel-squares.json") + " --nodes " +
                           scratchDir("solve-nodes-constant") + "/nodes.csv",
                       &log),
            0);
  EXPECT_NE(log.find("--basis linear"), std::string::npos) << log;
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
