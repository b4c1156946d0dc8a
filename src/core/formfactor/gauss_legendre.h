// Gauss-Legendre rules on [0, 1], computed once by Newton iteration on the Legendre polynomials.
#pragma once

#include <vector>

namespace rt {

struct QuadratureRule {
  std::vector<double> nodes;    // in (0, 1)
  std::vector<double> weights;  // sum to 1
};

// The n-point rule (1 <= n <= 64), exact for polynomials of degree 2n - 1. Thread-safe; rules are cached.
const QuadratureRule& gaussLegendre(int n);

}  // namespace rt
