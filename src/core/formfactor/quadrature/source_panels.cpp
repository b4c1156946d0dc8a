#include "core/formfactor/quadrature/source_panels.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/check.h"

namespace rt {
namespace {

// Safety factor of the bound M rho^-2n: the n x n tensor rule errs in both directions, and the integrand's
// size on the ellipse is only estimated. Calibrated so that the bound stays above the measured error on
// parallel, perpendicular and skewed squares at every distance (tests/core/formfactor_quadrature_test.cpp).
constexpr double kSafety = 8;

}  // namespace

std::array<SourcePanel, 4> splitPanel(const SourcePanel& panel) {
  const auto& v = panel.v;
  std::array<SourcePanel, 4> out;
  if (panel.count == 4) {
    const Vec3 m01 = 0.5 * (v[0] + v[1]), m12 = 0.5 * (v[1] + v[2]), m23 = 0.5 * (v[2] + v[3]),
               m30 = 0.5 * (v[3] + v[0]), c = panel.centre();
    out[0] = {v[0], m01, c, m30};
    out[1] = {m01, v[1], m12, c};
    out[2] = {c, m12, v[2], m23};
    out[3] = {m30, c, m23, v[3]};
    return out;
  }
  const Vec3 m01 = 0.5 * (v[0] + v[1]), m12 = 0.5 * (v[1] + v[2]), m20 = 0.5 * (v[2] + v[0]);
  out[0] = {v[0], m01, m20};
  out[1] = {m01, v[1], m12};
  out[2] = {m20, m12, v[2]};
  out[3] = {m01, m12, m20};
  return out;
}

void gaussPoints(const SourcePanel& panel, int n, PanelPoints& out) {
  RT_CHECK(n >= 1 && n * n <= PanelPoints::kMax, "a Gauss rule of more points than PanelPoints holds");
  out.count = 0;
  forEachGaussPoint(panel, n, [&](const Vec3& x, double w) {
    out.x[static_cast<std::size_t>(out.count)] = x;
    out.weight[static_cast<std::size_t>(out.count)] = w;
    ++out.count;
  });
}

double panelGap(const SourcePanel& panel, const ReceiverBound& receiver) {
  const double spheres = (panel.centre() - receiver.centre).norm() - panel.radius() - receiver.radius;
  double height = INFINITY;
  for (int k = 0; k < panel.count; ++k)
    height = std::min(height,
                      std::abs(receiver.normal.dot(panel.v[static_cast<std::size_t>(k)] - receiver.point)));
  return std::max(spheres, height);
}

int gaussOrderFor(const SourcePanel& panel, const ReceiverBound& receiver, double tolerance) {
  return gaussOrderFor(panelGap(panel, receiver), panel.longestEdge(), panel.count, receiver.area, tolerance);
}

int gaussOrderFor(double gap, double h, int corners, double receiverArea, double tolerance) {
  if (!(gap > 0)) return 0;
  const double ratio = gap / h;
  const double rho = 2 * ratio + std::sqrt(1 + 4 * ratio * ratio);
  const double size = std::min(1.0, receiverArea / (std::numbers::pi * gap * gap));
  const double needed = kSafety * size / tolerance;
  if (needed <= 1) return 1;
  // A triangle's collapsed rule carries the Jacobian u in its integrand, which costs one power of rho (the
  // n x n rule is exact to degree 2n - 2 in u, not 2n - 1): M rho^(1 - 2n).
  // The least n with rho^(2n - lost) >= needed, by multiplication: a logarithm per pair cost more than the
  // rest of the choice.
  double power = corners == 3 ? rho : rho * rho;  // rho^(2n - lost) for n = 1
  const double step = rho * rho;
  for (int n = 1; n <= kMaxOrder; ++n, power *= step)
    if (power >= needed) return n;
  return 0;
}

int panelsOf(const Vec3* polygon, int count, SourcePanel* out, int capacity) {
  if (count < 3) return 0;
  if (count <= 4) {
    out[0].count = count;
    for (int k = 0; k < count; ++k) out[0].v[static_cast<std::size_t>(k)] = polygon[k];
    return 1;
  }
  // A fan of quadrilaterals from the first corner (convex, as the polygon is), the last one a triangle when
  // the count is odd: half the panels of a fan of triangles, each by the tensor rule.
  // A caller's room for fewer panels than the fan has would drop part of the polygon: a bug, not a limit.
  RT_CHECK(capacity >= (count - 1) / 2, "room for fewer panels than the polygon's fan has");
  int made = 0;
  int t = 1;
  for (; t + 2 < count && made < capacity; t += 2)
    out[made++] = {polygon[0], polygon[t], polygon[t + 1], polygon[t + 2]};
  if (t + 1 < count && made < capacity) out[made++] = {polygon[0], polygon[t], polygon[t + 1]};
  return made;
}

}  // namespace rt
