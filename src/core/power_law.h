// Fitting a power law y = c x^s to measurements: the slope s of a log-log plot, the convergence order the
// benchmarks and the lessons' figures report.
#pragma once

#include <vector>

namespace rt {

// Least-squares slope of log y against log x over the points where both are positive (0 with fewer than
// two).
double logLogSlope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace rt
