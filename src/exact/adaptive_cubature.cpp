#include "exact/adaptive_cubature.h"

#include <cmath>
#include <numbers>
#include <queue>

#include "core/polygon.h"

namespace rt::exact {
namespace {

// Gauss-Legendre nodes and weights on [0, 1] by Newton iteration on the Legendre polynomial.
void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(n, 0);
  weights.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1;
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    nodes[i] = 0.5 * (1 - z);
    weights[i] = 1.0 / ((1 - z * z) * dp * dp);  // (2 / ((1-z^2) p'^2)) / 2 for [0, 1]
  }
}

struct Cell {
  Polygon vertices;
  double coarse = 0;
  double fine = 0;
  std::vector<double>
      childCoarse;  // rule on each child: the children's coarse estimates when this cell is split
  double error() const { return std::abs(fine - coarse); }
  bool operator<(const Cell& other) const { return error() < other.error(); }
};

}  // namespace

std::vector<Polygon> splitCell(const Polygon& c) {
  if (c.size() > 4) return fanTriangulate(c);  // an n-gon element: its fan triangles are the children
  if (c.size() == 3) {
    const Vec3 ab = 0.5 * (c[0] + c[1]), bc = 0.5 * (c[1] + c[2]), ca = 0.5 * (c[2] + c[0]);
    return {{c[0], ab, ca}, {ab, c[1], bc}, {ca, bc, c[2]}, {bc, ca, ab}};
  }
  const Vec3 m01 = 0.5 * (c[0] + c[1]), m12 = 0.5 * (c[1] + c[2]), m23 = 0.5 * (c[2] + c[3]),
             m30 = 0.5 * (c[3] + c[0]), center = 0.25 * (c[0] + c[1] + c[2] + c[3]);
  return {
      {c[0], m01, center, m30}, {m01, c[1], m12, center}, {center, m12, c[2], m23}, {m30, center, m23, c[3]}};
}

AdaptiveCubature::AdaptiveCubature(CubatureSettings settings) : settings_(std::move(settings)) {
  gaussLegendre(std::max(1, settings_.order), nodes_, weights_);
}

std::vector<WeightedPoint> AdaptiveCubature::rulePoints(const Polygon& c) const {
  std::vector<WeightedPoint> points;
  if (c.size() > 4) {  // an n-gon element: the rule on each fan triangle
    for (const Polygon& t : fanTriangulate(c))
      for (const WeightedPoint& p : rulePoints(t)) points.push_back(p);
    return points;
  }
  const std::size_t n = nodes_.size();
  points.reserve(n * n);
  if (c.size() == 3) {
    // Collapsed (Duffy) map p = a + u (b - a) + u v (c - b): Jacobian u |(b - a) x (c - b)|.
    const Vec3 e1 = c[1] - c[0], e2 = c[2] - c[1];
    const double scale = e1.cross(e2).norm();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        const double u = nodes_[i], v = nodes_[j];
        points.push_back({c[0] + u * e1 + u * v * e2, weights_[i] * weights_[j] * u * scale});
      }
    return points;
  }
  // Bilinear map of the unit square; the Jacobian is linear in (u, v).
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const double u = nodes_[i], v = nodes_[j];
      const Vec3 p = (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] + (1 - u) * v * c[3];
      const Vec3 du = (1 - v) * (c[1] - c[0]) + v * (c[2] - c[3]);
      const Vec3 dv = (1 - u) * (c[3] - c[0]) + u * (c[2] - c[1]);
      points.push_back({p, weights_[i] * weights_[j] * du.cross(dv).norm()});
    }
  return points;
}

CubatureResult AdaptiveCubature::integrate(const Polygon& domain, const std::function<double(const Vec3&)>& f,
                                           std::vector<WeightedPoint>* finalPoints) const {
  if (domain.size() < 3) return {};
  return integrateCells({domain}, f, finalPoints);
}

CubatureResult AdaptiveCubature::integrateCells(const std::vector<Polygon>& cells,
                                                const std::function<double(const Vec3&)>& f,
                                                std::vector<WeightedPoint>* finalPoints) const {
  CubatureResult result;
  auto rule = [&](const Polygon& cell) {
    double sum = 0;
    for (const WeightedPoint& p : rulePoints(cell)) sum += p.weight * f(p.position);
    result.evaluations += static_cast<long>(nodes_.size() * nodes_.size());
    return sum;
  };
  // A cell knows its coarse estimate; refining it means evaluating the rule on its four children.
  auto refine = [&](Cell& cell) {
    cell.childCoarse.clear();
    cell.fine = 0;
    for (const Polygon& child : splitCell(cell.vertices)) {
      cell.childCoarse.push_back(rule(child));
      cell.fine += cell.childCoarse.back();
    }
  };

  std::vector<Polygon> start;
  for (const Polygon& cell : cells) {
    if (cell.size() < 3) continue;
    if (cell.size() <= 4) {
      start.push_back(cell);
    } else {
      for (Polygon& triangle : fanTriangulate(cell)) start.push_back(std::move(triangle));
    }
  }
  for (int s = 0; s < settings_.initialSplits; ++s) {
    std::vector<Polygon> next;
    for (const Polygon& c : start)
      for (Polygon& child : splitCell(c)) next.push_back(std::move(child));
    start = std::move(next);
  }

  std::priority_queue<Cell> queue;
  double total = 0, error = 0;
  for (const Polygon& c : start) {
    Cell cell{c, 0, 0, {}};
    cell.coarse = rule(c);
    refine(cell);
    total += cell.fine;
    error += cell.error();
    queue.push(std::move(cell));
  }
  while (!queue.empty() && error > settings_.tolerance(total)) {
    if (result.evaluations >= settings_.maxEvaluations) {
      result.converged = false;
      break;
    }
    Cell worst = queue.top();
    queue.pop();
    total -= worst.fine;
    error -= worst.error();
    const std::vector<Polygon> children = splitCell(worst.vertices);
    for (std::size_t k = 0; k < children.size(); ++k) {
      Cell child{children[k], worst.childCoarse[k], 0, {}};
      refine(child);
      total += child.fine;
      error += child.error();
      queue.push(std::move(child));
    }
  }
  // Re-add from scratch: the running sums drift by rounding over many updates.
  result.value = 0;
  result.errorEstimate = 0;
  while (!queue.empty()) {
    const Cell& cell = queue.top();
    result.value += cell.fine;
    result.errorEstimate += cell.error();
    if (finalPoints)
      for (const Polygon& child : splitCell(cell.vertices))
        for (const WeightedPoint& p : rulePoints(child)) finalPoints->push_back(p);
    queue.pop();
  }
  return result;
}

}  // namespace rt::exact
