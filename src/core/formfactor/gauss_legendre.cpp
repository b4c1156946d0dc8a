#include "core/formfactor/gauss_legendre.h"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rt {
namespace {

QuadratureRule computeRule(int n) {
  QuadratureRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int k = 0; k < n; ++k) {
    // Tricomi's initial guess, then Newton on P_n(x) = 0.
    double x = std::cos(std::numbers::pi * (k + 0.75) / (n + 0.5));
    double derivative = 1;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1, p1 = x;
      for (int m = 2; m <= n; ++m) {
        const double p2 = ((2.0 * m - 1) * x * p1 - (m - 1.0) * p0) / m;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    // Map from [-1, 1] to [0, 1]: weights halve.
    rule.nodes[k] = 0.5 * (1 - x);
    rule.weights[k] = 1.0 / ((1 - x * x) * derivative * derivative);
  }
  return rule;
}

}  // namespace

const QuadratureRule& gaussLegendre(int n) {
  if (n < 1 || n > 64) throw std::invalid_argument("Gauss-Legendre order must be in 1..64");
  // Built on first use of the table (thread-safe static initialisation).
  static const std::array<QuadratureRule, 65> rules = [] {
    std::array<QuadratureRule, 65> all;
    for (int m = 1; m <= 64; ++m) all[m] = computeRule(m);
    return all;
  }();
  return rules[n];
}

}  // namespace rt
