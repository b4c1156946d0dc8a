// Run time against error from a file: the CSV tables of `radiosity bench formfactors` (method, parameter,
// seconds, rms_error, ...) and `radiosity bench solvers` (solver, iteration, seconds, ..., relative_error,
// residual). Charts of measured timings cannot be reproduced, so the run-time-against-error view can draw a
// table measured once (and its image test a fixed one). Public header: no VTK.
#pragma once

#include <string>
#include <vector>

#include "viz/chart.h"

namespace rt::viz {

struct TimingTable {
  std::vector<Series> series;  // one per value of the first column, in order of appearance; x = seconds
  std::string errorColumn;     // the column used for y
};

// The first column names the series; x is the `seconds` column; y the first of `rms_error`, `relative_error`,
// `error`, `residual` present in the header. Throws rt::InputError naming the file and line for a missing
// file, a header without those columns, or a row with a wrong field count or a value that is not a number.
TimingTable readTimingTable(const std::string& path);

}  // namespace rt::viz
