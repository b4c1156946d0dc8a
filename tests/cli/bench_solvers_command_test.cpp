// radiosity bench solvers: every solver's error against the direct solution per iteration in a CSV, the noise
// of stochastic Jacobi against its ray budget, and (with the visualisation library) the two charts as PNG and
// SVG.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_paths.h"
#ifdef RT_HAVE_VIZ
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#endif

namespace rt::test {
namespace {

// One run shared by the tests below: the furnace cube split 2 x 2 (24 elements) is solved in well under a
// second.
const std::string& benchOutput(std::string* log = nullptr) {
  static std::string output;
  static std::string runLog;
  static int status = -1;
  if (status < 0) {
    output = scratchDir("bench-solvers");
    status = runCommand(cliPath() + " bench solvers --scene " + sourcePath("scenes/furnace-cube.json") +
                            " --subdivide 2 --formfactors analytic --output " + output,
                        &runLog);
  }
  EXPECT_EQ(status, 0) << runLog;
  if (log) *log = runLog;
  return output;
}

TEST(BenchSolversCommand, TableHasEverySolverAndTheDeterministicOnesReachTheDirectSolution) {
  std::string log;
  const std::string dir = benchOutput(&log);
  const auto rows = readCsv(dir + "/solvers.csv");
  ASSERT_GT(rows.size(), 8u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"solver", "iteration", "seconds", "rays", "relative_error",
                                               "residual"}));
  std::map<std::string, std::vector<std::vector<std::string>>> bySolver;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), 6u) << "row " << r;
    bySolver[rows[r][0]].push_back(rows[r]);
  }
  for (const std::string name : {"direct", "jacobi", "gauss-seidel", "southwell", "progressive", "bounces",
                                 "stochastic-jacobi", "random-walk", "local-lines"}) {
    ASSERT_TRUE(bySolver.count(name)) << name;
    const auto& samples = bySolver[name];
    for (std::size_t k = 0; k < samples.size(); ++k) {
      EXPECT_EQ(std::stoi(samples[k][1]), static_cast<int>(k + 1)) << name;  // one row per iteration
      EXPECT_TRUE(std::isfinite(std::stod(samples[k][4]))) << name;
    }
    const double finalError = std::stod(samples.back()[4]);
    const bool stochastic = name == std::string("stochastic-jacobi") || name == std::string("random-walk") ||
                            name == std::string("local-lines");
    EXPECT_LT(finalError, stochastic ? 0.05 : 1e-8) << name;
    if (stochastic) {
      EXPECT_GT(std::stol(samples.back()[3]), 0) << name << ": rays are counted";
    }
    // The summary on stdout names the solver with its status.
    EXPECT_NE(log.find(name), std::string::npos) << log;
  }
  EXPECT_EQ(std::stod(bySolver["direct"].front()[4]), 0.0);
  EXPECT_NE(log.find("24 elements"), std::string::npos) << log;
}

TEST(BenchSolversCommand, StochasticNoiseFallsWithTheRayBudget) {
  const auto rows = readCsv(benchOutput() + "/stochastic.csv");
  ASSERT_EQ(rows.size(), 5u);  // header + budgets of 10, 100, 1000, 10000 rays per element
  EXPECT_EQ(rows[0][0], "rays_per_iteration");
  // x1000 rays: the error falls by about sqrt(1000) ~ 32; allow a wide margin for noise.
  const double fewRays = std::stod(rows[1][3]), manyRays = std::stod(rows[4][3]);
  EXPECT_LT(manyRays, fewRays / 5.0) << fewRays << " -> " << manyRays;
  for (std::size_t r = 1; r < rows.size(); ++r) EXPECT_GT(std::stod(rows[r][4]), 0.0) << "reported error";
}

#ifdef RT_HAVE_VIZ
TEST(BenchSolversCommand, ChartsAreWrittenAndNotBlank) {
  const std::string dir = benchOutput();
  for (const std::string chart : {"solvers_error_vs_time", "solvers_error_vs_iterations"}) {
    std::ifstream svg(dir + "/" + chart + ".svg");
    ASSERT_TRUE(svg.good()) << chart;
    const std::string text{std::istreambuf_iterator<char>(svg), std::istreambuf_iterator<char>()};
    EXPECT_NE(text.find("<svg"), std::string::npos) << chart;
    // The visible text is drawn as paths; the SVG's description names the series, as the legend does.
    EXPECT_NE(text.find("<desc>"), std::string::npos) << chart;
    EXPECT_NE(text.find("gauss-seidel"), std::string::npos) << chart << ": the description names the solvers";

    vtkNew<vtkPNGReader> reader;
    reader->SetFileName((dir + "/" + chart + ".png").c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    ASSERT_GT(dims[0], 100) << chart;
    ASSERT_GT(dims[1], 100) << chart;
    // Many distinct colours: axes, text and several coloured lines, not a blank canvas.
    std::set<int> colours;
    const int components = image->GetNumberOfScalarComponents();
    ASSERT_GE(components, 3);
    for (int y = 0; y < dims[1]; y += 2)
      for (int x = 0; x < dims[0]; x += 2) {
        const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
        colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
      }
    EXPECT_GT(colours.size(), 20u) << chart;
  }
}
#endif

}  // namespace
}  // namespace rt::test
