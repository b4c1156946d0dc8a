#include "core/formfactor/quadrature/unoccluded_integral.h"

#include <algorithm>
#include <array>
#include <numbers>

#include "core/formfactor/analytic.h"
#include "core/formfactor/lambert_four.h"

namespace rt {
namespace {

constexpr int kMaxUnoccludedDepth = 6;

// F(dA_x -> receiver) dA_x over a far panel by one point on each side: the kernel cos cos / (pi r^2) at the
// panels' one-point Gauss nodes, times both weights. The a-priori bound (source_panels.h) is symmetric in
// the two elements: the receiver's one-point rule from a fixed x errs by the same M rho^-2 as the source's,
// with rho from the receiver's own edge. Each side gets half the tolerance; the pair must face itself at
// both nodes. A fifth of the cost of Lambert's formula, whose four arctangents dominate far pairs.
bool farFieldPair(const OnePoint& source, const OnePoint& receiver, const ReceiverBound& bound,
                  const Vec3& normal, double gap, double tolerance, double& sum) {
  if (receiver.corners == 0 || source.corners == 0 || !(gap > 0)) return false;
  if (gaussOrderFor(gap, std::max(source.longest, receiver.longest),
                    std::min(source.corners, receiver.corners), bound.area, 0.5 * tolerance) != 1)
    return false;
  const Vec3 d = receiver.node - source.node;
  const double r2 = d.squaredNorm(), cx = normal.dot(d), cy = -bound.normal.dot(d);
  if (!(cx > 0 && cy > 0)) return false;
  sum = source.weight * receiver.weight * cx * cy / (std::numbers::pi * r2 * r2);
  return true;
}

OnePoint onePointOf(const SourcePanel& panel) {
  OnePoint side;
  forEachGaussPoint(panel, 1, [&](const Vec3& x, double w) { side.node = x, side.weight = w; });
  side.longest = panel.longestEdge();
  side.corners = panel.count;
  return side;
}

}  // namespace

// An element's own one-point rule, made once with its other measures (it is whole).
OnePoint onePointOf(const QuadratureScene::Measure& m) {
  return OnePoint{m.node, m.weight, m.longest, m.corners};
}

double integrateUnoccluded(const SourcePanel& panel, const ReceiverBound& bound,
                           const ConvexPolygon& receiver, const Vec3& normal, double tolerance, int depth,
                           PairWork& work, double gap, double edge, const OnePoint* far,
                           const OnePoint* own) {
  if (far && far->corners > 0) {
    double sum = 0;
    if (farFieldPair(own ? *own : onePointOf(panel), *far, bound, normal,
                     gap >= 0 ? gap : panelGap(panel, bound), tolerance, sum)) {
      ++work.points;
      return sum;
    }
  }
  int n = gap >= 0 ? gaussOrderFor(gap, edge, panel.count, bound.area, tolerance)
                   : gaussOrderFor(panel, bound, tolerance);
  if (n == 0 && depth < kMaxUnoccludedDepth) {
    double sum = 0;
    for (const SourcePanel& child : splitPanel(panel))
      sum += integrateUnoccluded(child, bound, receiver, normal, tolerance, depth + 1, work);
    return sum;
  }
  if (n == 0) n = kMaxOrder;
  // Four points at a time (lambert_four.h), all over the one receiver.
  PanelPoints points;
  gaussPoints(panel, n, points);
  double sum = 0;
  int p = 0;
  for (; p + 4 <= points.count; p += 4) {
    std::array<double, 4> value;
    lambertContourSum4(&points.x[static_cast<std::size_t>(p)], normal, receiver.v.data(), 0, receiver.count,
                       value.data());
    for (std::size_t k = 0; k < 4; ++k)
      sum += points.weight[static_cast<std::size_t>(p) + k] * std::max(0.0, value[k]);
  }
  for (; p < points.count; ++p)
    sum += points.weight[static_cast<std::size_t>(p)] *
           std::max(0.0, lambertContourSum(points.x[static_cast<std::size_t>(p)], normal, receiver.v.data(),
                                           receiver.count));
  work.points += n * n;
  return sum;
}

// A convex polygon as panels (panelsOf()), appended to `out`: room for exactly the panels its fan makes
// (one, or (count - 1) / 2), so whatever its corner count all of it is kept and little is zeroed.
void appendPanels(const ConvexPolygon& polygon, std::vector<SourcePanel>& out) {
  const std::size_t first = out.size();
  out.resize(first + static_cast<std::size_t>(std::max(1, (polygon.count - 1) / 2)));
  const int made =
      panelsOf(polygon.v.data(), polygon.count, out.data() + first, static_cast<int>(out.size() - first));
  out.resize(first + static_cast<std::size_t>(made));
}

void appendPanels(const std::vector<ConvexPolygon>& polygons, std::vector<SourcePanel>& out) {
  out.clear();
  for (const ConvexPolygon& polygon : polygons) appendPanels(polygon, out);
}

}  // namespace rt
