// The point-query numbers of docs/benchmarks.md: irradiance on the floor of the closed Cornell box by the
// two-pass method, end to end (the command, wall clock), against the stored path-traced reference
// (tests/data/pathtrace/README.md). Disabled by default (a benchmark, not a timed test); run with
//   cli_tests --gtest_also_run_disabled_tests --gtest_filter='PointQueryBenchmark.*'
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_paths.h"

namespace rt::test {
namespace {

// Column name -> values, for a CSV with a header.
std::map<std::string, std::vector<std::string>> readColumns(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string cell; std::getline(header, cell, ',');) names.push_back(cell);
  std::map<std::string, std::vector<std::string>> columns;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::size_t k = 0;
    for (std::string cell; std::getline(row, cell, ',') && k < names.size(); ++k)
      columns[names[k]].push_back(cell);
  }
  return columns;
}

struct Score {
  double rms = 0, largest = 0, mean = 0, covered = 0;
  double noise = 0;  // RMS of the reported standard errors, relative
};

Score score(const std::string& reference, const std::string& answer) {
  auto ref = readColumns(reference), got = readColumns(answer);
  Score s;
  int n = 0;
  for (const char* c : {"r", "g", "b"}) {
    const std::string h = std::string("H_") + c, e = h + "_error";
    for (std::size_t p = 0; p < ref[h].size() && p < got[h].size(); ++p) {
      const double truth = std::stod(ref[h][p]), value = std::stod(got[h][p]);
      const double relative = (value - truth) / truth;
      s.rms += relative * relative;
      s.mean += relative;
      s.largest = std::max(s.largest, std::abs(relative));
      s.noise += std::pow(std::stod(got[e][p]) / truth, 2);
      s.covered += std::abs(value - truth) <= 3 * std::hypot(std::stod(ref[e][p]), std::stod(got[e][p]));
      ++n;
    }
  }
  s.rms = std::sqrt(s.rms / n);
  s.noise = std::sqrt(s.noise / n);
  s.mean /= n;
  s.covered /= n;
  return s;
}

TEST(PointQueryBenchmark, DISABLED_ClosedCornellBoxFloor) {
  const std::string points = dataPath("pathtrace/cornell-closed-floor-points.csv");
  const std::string reference = dataPath("pathtrace/cornell-closed-floor-reference.csv");
  const std::string out = scratchDir("point-query-benchmark") + "/H.csv";
  std::printf(
      "| settings | elements | seconds | RMS relative error | largest | mean | reported noise (RMS) | "
      "within 3 sigma |\n");
  for (const char* settings :
       {"--no-mesh-error", "", "--no-mesh-error --near-rays 2", "--no-mesh-error --near-rays 4",
        "--no-mesh-error --seed 2", "--no-mesh-error --seed 3",
        "--no-mesh-error --gather-rays 16384 --near-rays 8"}) {
    std::string log;
    const auto start = std::chrono::steady_clock::now();
    ASSERT_EQ(runCommand(cliPath() + " irradiance " + sourcePath("scenes/cornell-box-closed.json") +
                             " --points " + points + " --output " + out + " " + settings,
                         &log),
              0)
        << log;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Score s = score(reference, out);
    const auto at = log.find("solution (");
    std::printf("| `%s` | %s | %.2f | %.4f | %.4f | %+.4f | %.4f | %.3f |\n", settings,
                at == std::string::npos ? "?" : log.substr(at + 10, log.find(' ', at + 10) - at - 10).c_str(),
                seconds, s.rms, s.largest, s.mean, s.noise, s.covered);
    std::fflush(stdout);
    // Known answer, loosely: the two-pass method is within a few percent of the reference everywhere.
    EXPECT_LT(s.rms, 0.03);
    EXPECT_LT(s.largest, 0.1);
  }
}

// The closed box with the light flush in a cut ceiling and hung 0.1 mm and 1 cm below an uncut one, at the 82
// floor points: the two-pass defaults (best wall time of 3) against the path tracer at several path counts
// (best of 3 each), and the path count and wall time the path tracer needs for the two-pass RMS.
TEST(PointQueryBenchmark, DISABLED_NearCeilingLights) {
  const std::string points = dataPath("pathtrace/cornell-closed-floor-points-82.csv");
  const std::string out = scratchDir("point-query-benchmark-lights") + "/H.csv";
  struct Case {
    const char* scene;
    const char* reference;
  };
  auto run = [&](const std::string& scene, const std::string& settings, const std::string& reference,
                 double& seconds) {
    seconds = 1e300;
    Score s;
    for (int k = 0; k < 3; ++k) {
      std::string log;
      const auto start = std::chrono::steady_clock::now();
      EXPECT_EQ(runCommand(cliPath() + " irradiance " + sourcePath("scenes/" + scene) + " --points " +
                               points + " --output " + out + " " + settings,
                           &log),
                0)
          << log;
      seconds =
          std::min(seconds, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      s = score(dataPath("pathtrace/" + reference), out);
    }
    return s;
  };
  std::printf("| scene | settings | seconds (best of 3) | RMS | largest | mean |\n");
  for (const Case& c :
       {Case{"cornell-box-closed.json", "cornell-closed-floor-reference-82.csv"},
        Case{"cornell-box-closed-light-0.1mm.json", "cornell-closed-light-0.1mm-floor-reference-82.csv"},
        Case{"cornell-box-closed-light-1cm.json", "cornell-closed-light-1cm-floor-reference-82.csv"}}) {
    double twoPassSeconds = 0;
    const Score twoPass = run(c.scene, "--no-mesh-error", c.reference, twoPassSeconds);
    std::printf("| `%s` | two-pass `--no-mesh-error` | %.2f | %.4f | %.4f | %+.4f |\n", c.scene,
                twoPassSeconds, twoPass.rms, twoPass.largest, twoPass.mean);
    // The path tracer's RMS and time at each count; the count for the two-pass RMS interpolated between the
    // two counts around it (or extrapolated from the last two) as RMS ~ paths^-k, the time linearly in paths.
    const std::vector<int> counts{4096, 16384, 65536};
    std::vector<double> rms, seconds;
    for (int paths : counts) {
      double t = 0;
      const Score traced = run(c.scene, "--path-trace " + std::to_string(paths), c.reference, t);
      std::printf("| `%s` | `--path-trace %d` | %.2f | %.4f | %.4f | %+.4f |\n", c.scene, paths, t,
                  traced.rms, traced.largest, traced.mean);
      rms.push_back(traced.rms);
      seconds.push_back(t);
      std::fflush(stdout);
    }
    std::size_t k = 1;
    while (k + 1 < counts.size() && rms[k] > twoPass.rms) ++k;
    const double order = std::log(rms[k - 1] / rms[k]) / std::log(double(counts[k]) / counts[k - 1]);
    const double paths = counts[k - 1] * std::pow(rms[k - 1] / twoPass.rms, 1 / order);
    const double time = seconds[k - 1] +
                        (seconds[k] - seconds[k - 1]) * (paths - counts[k - 1]) / (counts[k] - counts[k - 1]);
    std::printf("| `%s` | path tracer at the two-pass RMS (interpolated) | %.2f | %.4f | | %.0f paths |\n",
                c.scene, time, twoPass.rms, paths);
    std::fflush(stdout);
  }
}

}  // namespace
}  // namespace rt::test
