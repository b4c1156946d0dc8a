// Timing tables for the run-time-against-error chart: both benchmark CSV layouts, and errors naming the line.
#include <gtest/gtest.h>

#include <fstream>

#include "core/input_error.h"
#include "support/test_paths.h"
#include "viz/timing_table.h"

namespace rt::viz {
namespace {

std::string writeTable(const std::string& name, const std::string& text) {
  const std::string path = test::scratchDir("timing_table") + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(TimingTable, ReadsTheFormFactorBenchmark) {
  const TimingTable table = readTimingTable(test::sourcePath("tests/viz/data/bench-formfactors.csv"));
  EXPECT_EQ(table.errorColumn, "rms_error");
  ASSERT_EQ(table.series.size(), 5u);
  EXPECT_EQ(table.series[0].name, "hemicube");
  EXPECT_EQ(table.series[4].name, "analytic-visibility");
  for (const Series& s : table.series) {
    EXPECT_EQ(s.x.size(), s.y.size());
    EXPECT_GE(s.x.size(), 5u);
  }
}

TEST(TimingTable, ReadsTheSolverBenchmarkAndInterleavedRows) {
  const TimingTable table = readTimingTable(
      writeTable("solvers.csv",
                 "solver,iteration,seconds,rays,relative_error,residual\n"
                 "jacobi,1,0.001,0,0.5,0.4\ngauss-seidel,1,0.002,0,0.25,0.2\njacobi,2,0.003,0,0.125,0.1\n"));
  EXPECT_EQ(table.errorColumn, "relative_error");
  ASSERT_EQ(table.series.size(), 2u);
  EXPECT_EQ(table.series[0].name, "jacobi");
  EXPECT_EQ(table.series[0].x, (std::vector<double>{0.001, 0.003}));
  EXPECT_EQ(table.series[0].y, (std::vector<double>{0.5, 0.125}));
  EXPECT_EQ(table.series[1].y, (std::vector<double>{0.25}));
}

TEST(TimingTable, ErrorsNameTheFileAndLine) {
  const std::string bad = writeTable("bad.csv", "method,parameter,seconds,rms_error\nhemicube,16,fast,0.1\n");
  try {
    readTimingTable(bad);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, bad);
    EXPECT_EQ(e.where().line, 2);
    EXPECT_NE(e.message().find("fast"), std::string::npos);
  }
  EXPECT_THROW(readTimingTable(writeTable("short.csv", "method,seconds,rms_error\nhemicube,0.1\n")),
               InputError);
  EXPECT_THROW(readTimingTable(writeTable("noerror.csv", "method,seconds\nhemicube,0.1\n")), InputError);
  EXPECT_THROW(readTimingTable(writeTable("empty.csv", "")), InputError);
  EXPECT_THROW(readTimingTable("/nonexistent/table.csv"), InputError);
}

}  // namespace
}  // namespace rt::viz
