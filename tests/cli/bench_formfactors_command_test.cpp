// radiosity bench formfactors: every method's knob swept against a reference, in a CSV with the relative RMS
// error, the fitted slopes on stdout, and (with the visualisation library) the chart as PNG and SVG.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_paths.h"

namespace rt::test {
namespace {

TEST(BenchFormFactorsCommand, SweepsEveryMethodAgainstTheAnalyticReference) {
  // Two parallel squares: nothing can be occluded, so the reference is the analytic method, and every sweep
  // takes milliseconds.
  const std::string dir = scratchDir("bench-formfactors");
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " bench formfactors --scene " +
                           sourcePath("scenes/parallel-squares.json") + " --no-subdivide --output " + dir,
                       &log),
            0)
      << log;
  EXPECT_NE(log.find("reference: analytic"), std::string::npos) << log;
  std::ifstream in(dir + "/formfactors.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "method,parameter,seconds,rms_error,max_error,row_sum_error,relative_rms_error");
  std::map<std::string, std::vector<double>> relative;  // method -> relative RMS error per knob value
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 7u) << line;
    const double rms = std::stod(cells[3]), rel = std::stod(cells[6]);
    EXPECT_GE(rel, 0) << line;
    // Two elements with F = 0.19982...: the relative RMS is the RMS over the RMS of [0 F; F 0].
    EXPECT_NEAR(rel, rms / (0.19982489569838738 / std::sqrt(2.0)), 1e-3 * rel + 1e-12) << line;
    relative[cells[0]].push_back(rel);
  }
  for (const char* method : {"hemicube", "raycast", "montecarlo", "nusselt", "hybrid"})
    EXPECT_FALSE(relative[method].empty()) << method;
  // Two adjacent plates are a near pair for the hybrid method: exact, and nothing to occlude them.
  for (double rel : relative["hybrid"]) EXPECT_LT(rel, 1e-12);
  // The stochastic methods converge: the largest budget beats the smallest.
  EXPECT_LT(relative["raycast"].back(), relative["raycast"].front());
  EXPECT_LT(relative["montecarlo"].back(), relative["montecarlo"].front());
  EXPECT_NE(log.find("montecarlo           slope of log(rms error)"), std::string::npos) << log;
#ifdef RT_HAVE_VIZ
  EXPECT_GT(std::filesystem::file_size(dir + "/formfactors.png"), 1000u);
  EXPECT_GT(std::filesystem::file_size(dir + "/formfactors.svg"), 1000u);
#endif
}

}  // namespace
}  // namespace rt::test
