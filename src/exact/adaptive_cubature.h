// Globally adaptive cubature over a planar convex polygon: cells are triangles (collapsed Gauss-Legendre
// product rule) or quadrilaterals (bilinear Gauss-Legendre product rule). Each cell carries a coarse estimate
// (rule on the cell) and a refined one (rule on its four children); the cell with the largest |refined -
// coarse| is split until the sum of those differences is below the requested absolute tolerance. Shadow
// boundaries, where F(x) has kinks, attract the splits.
#pragma once

#include <functional>
#include <vector>

#include "core/vec.h"

namespace rt::exact {

struct CubatureSettings {
  int order = 5;  // Gauss-Legendre points per direction
  long maxEvaluations = 400000;
  int initialSplits = 0;  // uniform splits before adapting (guards small features both estimates would miss)
  // Absolute target as a function of the current estimate of the integral (relative targets need it).
  std::function<double(double)> tolerance = [](double) { return 1e-12; };
};

struct CubatureResult {
  double value = 0;
  double errorEstimate = 0;  // sum over final cells of |refined - coarse|
  long evaluations = 0;
  bool converged = true;
};

struct WeightedPoint {
  Vec3 position;
  double weight;  // area weight
};

class AdaptiveCubature {
 public:
  explicit AdaptiveCubature(CubatureSettings settings);
  // Integrates f over the polygon (3 or 4 vertices: one cell, more: fan triangles). `finalPoints`, when
  // given, receives the points and weights of the refined rule of every final cell.
  CubatureResult integrate(const Polygon& domain, const std::function<double(const Vec3&)>& f,
                           std::vector<WeightedPoint>* finalPoints = nullptr) const;
  // The same over a tiling of the domain into convex cells (more than 4 vertices: fan triangles), e.g. one
  // along which the integrand has kinks: the cells' boundaries then need no refinement.
  CubatureResult integrateCells(const std::vector<Polygon>& cells,
                                const std::function<double(const Vec3&)>& f,
                                std::vector<WeightedPoint>* finalPoints = nullptr) const;
  // The rule's points on one cell (3 or 4 vertices).
  std::vector<WeightedPoint> rulePoints(const Polygon& cell) const;

 private:
  CubatureSettings settings_;
  std::vector<double> nodes_, weights_;  // Gauss-Legendre on [0, 1]
};

// Four children of a triangle (midpoint split) or of a quadrilateral (bilinear split).
std::vector<Polygon> splitCell(const Polygon& cell);

}  // namespace rt::exact
