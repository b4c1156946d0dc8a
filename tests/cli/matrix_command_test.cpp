// radiosity matrix: F, K, rho, E and B in every export format, the spectral radius and the condition number
// it prints, and clear errors for LaTeX output of a large matrix and unknown formats.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_paths.h"

namespace rt::test {
namespace {

// Howell C-11: two unit squares at distance 1.
constexpr double kParallelSquares = 0.19982489569838738;
// The closed unit cube: opposite and adjacent faces.
constexpr double kCubeOpposite = 0.19982489569838738;
constexpr double kCubeAdjacent = 0.20004377607540316;

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::vector<double>> readCsvNumbers(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(std::stod(cell));
    rows.push_back(cells);
  }
  return rows;
}

// The number printed after `label` in the command's output (NaN when absent).
double printedNumber(const std::string& log, const std::string& label) {
  const auto at = log.find(label);
  if (at == std::string::npos) return std::nan("");
  return std::stod(log.substr(at + label.size()));
}

std::string matrixCommand(const std::string& scene, const std::string& arguments) {
  return cliPath() + " matrix " + sourcePath("scenes/" + scene) + " --no-subdivide " + arguments;
}

// The scenes below have nothing between their faces, where `analytic` is exact to rounding: the matrix
// algebra then shows to 1e-12, not to the default method's tolerance.
std::string exactMatrixCommand(const std::string& scene, const std::string& arguments) {
  return matrixCommand(scene, "--method analytic " + arguments);
}

TEST(MatrixCommand, AMethodThatIgnoresOccludersWarnsOnTheCornellBox) {
  // The blocks hide walls from the floor; analytic counts that light anyway. Nothing used to say so.
  const std::string dir = scratchDir("matrix-occluded");
  std::string log;
  ASSERT_EQ(
      runCommand(matrixCommand("cornell-box.json", "--method analytic --what F --output " + dir + "/F.csv"),
                 &log),
      0)
      << log;
  EXPECT_NE(log.find("warning: analytic ignored occluders for"), std::string::npos) << log;
  EXPECT_NE(log.find("rows of F sum to more than 1 (up to 1.2"), std::string::npos) << log;
  // The default method accounts for the blocks: no warning.
  ASSERT_EQ(runCommand(matrixCommand("cornell-box.json", "--what F --output " + dir + "/F2.csv"), &log), 0)
      << log;
  EXPECT_EQ(log.find("ignored occluders"), std::string::npos) << log;
  EXPECT_EQ(log.find("more than 1"), std::string::npos) << log;
}

TEST(MatrixCommand, KOfTheParallelSquaresAsCsvWithItsNumbers) {
  const std::string out = scratchDir("matrix-k") + "/K.csv";
  std::string log;
  ASSERT_EQ(runCommand(exactMatrixCommand("parallel-squares.json", "--output " + out), &log), 0) << log;
  // K = I - diag(rho) F with rho = (0, 0.5): only the receiver's row has an off-diagonal entry.
  const auto K = readCsvNumbers(out);
  ASSERT_EQ(K.size(), 2u);
  ASSERT_EQ(K[0].size(), 2u);
  EXPECT_DOUBLE_EQ(K[0][0], 1.0);
  EXPECT_DOUBLE_EQ(K[0][1], 0.0);
  EXPECT_NEAR(K[1][0], -0.5 * kParallelSquares, 1e-12);
  EXPECT_DOUBLE_EQ(K[1][1], 1.0);
  EXPECT_NE(log.find("elements: 2"), std::string::npos) << log;
  // rho F is nilpotent here (the source reflects nothing): spectral radius 0.
  EXPECT_NEAR(printedNumber(log, "spectral radius of rho F:"), 0.0, 1e-12) << log;
  // K = [1 0; -a 1] has singular values whose ratio is ((a + sqrt(a^2 + 4)) / 2)^2.
  const double a = 0.5 * kParallelSquares;
  const double condition = std::pow((a + std::sqrt(a * a + 4.0)) / 2.0, 2);
  EXPECT_NEAR(printedNumber(log, "condition number of K (2-norm):"), condition, 1e-8) << log;
}

TEST(MatrixCommand, FurnaceCubeSpectralRadiusIsRhoAndConditionFromItsEigenvalues) {
  const std::string out = scratchDir("matrix-furnace") + "/F.csv";
  std::string log;
  ASSERT_EQ(runCommand(exactMatrixCommand("furnace-cube.json", "--what F --output " + out), &log), 0) << log;
  const auto F = readCsvNumbers(out);
  ASSERT_EQ(F.size(), 6u);
  for (const auto& row : F) {
    ASSERT_EQ(row.size(), 6u);
    double sum = 0;
    for (double f : row) sum += f;
    EXPECT_NEAR(sum, 1.0, 1e-9);  // closed
  }
  // Rows of a closed scene sum to 1, so rho F = 0.5 F has spectral radius 0.5.
  EXPECT_NEAR(printedNumber(log, "spectral radius of rho F:"), 0.5, 1e-8) << log;
  // F is symmetric with eigenvalues 1, -b (x3) and b - 2a (x2): K = I - F/2 has extreme eigenvalues 0.5 and
  // 1 + a - b/2.
  const double condition = (1.0 + kCubeAdjacent - 0.5 * kCubeOpposite) / 0.5;
  EXPECT_NEAR(printedNumber(log, "condition number of K (2-norm):"), condition, 1e-8) << log;
}

TEST(MatrixCommand, RhoEAndBAreElementsByChannels) {
  const std::string dir = scratchDir("matrix-vectors");
  std::string log;
  for (const std::string what : {"rho", "E", "B"}) {
    ASSERT_EQ(runCommand(exactMatrixCommand("furnace-cube.json",
                                            "--what " + what + " --output " + dir + "/" + what + ".csv"),
                         &log),
              0)
        << log;
    const auto values = readCsvNumbers(dir + "/" + what + ".csv");
    ASSERT_EQ(values.size(), 6u) << what;
    const double expected = what == "rho" ? 0.5 : what == "E" ? 1.0 : 2.0;  // B = E / (1 - rho)
    for (const auto& row : values) {
      ASSERT_EQ(row.size(), 3u) << what;
      for (double v : row) EXPECT_NEAR(v, expected, 1e-9) << what;
    }
  }
}

TEST(MatrixCommand, MatrixMarketNpyAndLatexFormats) {
  const std::string dir = scratchDir("matrix-formats");
  std::string log;
  ASSERT_EQ(
      runCommand(exactMatrixCommand("parallel-squares.json", "--what F --output " + dir + "/F.mtx"), &log), 0)
      << log;
  std::istringstream mtx(readFile(dir + "/F.mtx"));
  std::string line;
  std::getline(mtx, line);
  EXPECT_EQ(line, "%%MatrixMarket matrix coordinate real general");
  while (std::getline(mtx, line) && line.rfind('%', 0) == 0) {
  }
  EXPECT_EQ(line, "2 2 2");  // two non-zeros: F_12 = F_21
  int i = 0, j = 0;
  double value = 0;
  mtx >> i >> j >> value;
  EXPECT_NEAR(value, kParallelSquares, 1e-12);

  ASSERT_EQ(runCommand(matrixCommand("parallel-squares.json", "--output " + dir + "/K.npy"), &log), 0) << log;
  const std::string npy = readFile(dir + "/K.npy");
  ASSERT_GT(npy.size(), 10u);
  EXPECT_EQ(npy.substr(0, 6), "\x93NUMPY");
  EXPECT_NE(npy.find("'descr': '<f8'"), std::string::npos);
  EXPECT_NE(npy.find("'shape': (2, 2)"), std::string::npos);
  const std::size_t header =
      10 + (static_cast<unsigned char>(npy[8]) | static_cast<unsigned char>(npy[9]) << 8);
  EXPECT_EQ(npy.size(), header + 4 * sizeof(double));

  ASSERT_EQ(runCommand(matrixCommand("parallel-squares.json", "--output " + dir + "/K.tex"), &log), 0) << log;
  const std::string tex = readFile(dir + "/K.tex");
  EXPECT_NE(tex.find("\\begin{bmatrix}"), std::string::npos) << tex;
  EXPECT_NE(tex.find("1 & 0 \\\\"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\end{bmatrix}"), std::string::npos) << tex;
}

TEST(MatrixCommand, LatexOfALargeMatrixIsAClearErrorBeforeAnyWork) {
  const std::string out = scratchDir("matrix-latex-large") + "/K.tex";
  std::string log;
  // 6 faces x 2 x 2 = 24 elements: more than LaTeX output accepts.
  EXPECT_NE(runCommand(cliPath() + " matrix " + sourcePath("scenes/furnace-cube.json") +
                           " --subdivide 2 --output " + out,
                       &log),
            0);
  EXPECT_NE(log.find("LaTeX output is limited to 20 x 20"), std::string::npos) << log;
  EXPECT_NE(log.find("24 x 24"), std::string::npos) << log;
  EXPECT_NE(log.find(".csv"), std::string::npos) << log;
  EXPECT_EQ(log.find("form factors ("), std::string::npos) << "F was computed before the error: " << log;
  EXPECT_FALSE(std::ifstream(out).good());
}

TEST(MatrixCommand, UnknownFormatAndUnknownWhatAreClearErrors) {
  const std::string dir = scratchDir("matrix-errors");
  std::string log;
  EXPECT_NE(runCommand(matrixCommand("parallel-squares.json", "--output " + dir + "/K.xls"), &log), 0);
  EXPECT_NE(log.find("K.xls"), std::string::npos) << log;
  EXPECT_NE(log.find(".mtx"), std::string::npos) << log;
  EXPECT_NE(runCommand(matrixCommand("parallel-squares.json", "--what G --output " + dir + "/G.csv"), &log),
            0);
  EXPECT_NE(log.find("--what"), std::string::npos) << log;
}

}  // namespace
}  // namespace rt::test
