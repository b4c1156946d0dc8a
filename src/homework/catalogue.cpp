#include "homework/catalogue.h"

#include <cmath>
#include <numbers>

#include "core/formfactor/gauss_legendre.h"
#include "homework/exercise.h"

namespace rt::homework {
namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

// Lambert: F(dA -> polygon) = (1/2pi) sum_k beta_k n . (R_k x R_k+1) / |R_k x R_k+1|, for a polygon wholly in
// front of the point; the sign is made positive (the polygon's orientation does not matter here).
double lambert(const Vec3& x, const Vec3& n, const Polygon& polygon) {
  double sum = 0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Vec3 a = (polygon[k] - x).normalized(), b = (polygon[(k + 1) % polygon.size()] - x).normalized();
    const Vec3 c = a.cross(b);
    if (c.norm() < 1e-15) continue;
    sum += std::atan2(c.norm(), a.dot(b)) * n.dot(c.normalized());
  }
  return std::abs(sum) / (2 * kPi);
}

// Directly opposed parallel rectangles a x b at distance c (Howell's catalogue, C-11).
double parallelRectangles(double a, double b, double c, std::vector<std::string>& steps) {
  const double X = a / c, Y = b / c;
  const double t1 = 0.5 * std::log((1 + X * X) * (1 + Y * Y) / (1 + X * X + Y * Y));
  const double t2 = X * std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y));
  const double t3 = Y * std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X));
  const double t4 = -X * std::atan(X), t5 = -Y * std::atan(Y);
  const double F = 2 / (kPi * X * Y) * (t1 + t2 + t3 + t4 + t5);
  steps.push_back("$X = a/c = " + num(X, 6) + "$, $Y = b/c = " + num(Y, 6) + "$.");
  steps.push_back(
      "Catalogue formula for directly opposed rectangles: $F_{12} = \\frac{2}{\\pi X Y}\\big[\\ln\\sqrt{"
      "\\frac{(1+X^2)(1+Y^2)}{1+X^2+Y^2}} + X\\sqrt{1+Y^2}\\arctan\\frac{X}{\\sqrt{1+Y^2}} + "
      "Y\\sqrt{1+X^2}\\arctan\\frac{Y}{\\sqrt{1+X^2}} - X\\arctan X - Y\\arctan Y\\big]$.");
  steps.push_back("Terms: $" + num(t1, 6) + "$, $" + num(t2, 6) + "$, $" + num(t3, 6) + "$, $" + num(t4, 6) +
                  "$, $" + num(t5, 6) + "$; their sum is $" + num(t1 + t2 + t3 + t4 + t5, 6) + "$.");
  return F;
}

// From a w x l rectangle to an h x l rectangle sharing the edge of length l, at a right angle (C-14).
double perpendicularRectangles(double w, double h, double l, std::vector<std::string>& steps) {
  const double W = w / l, H = h / l, S = W * W + H * H;
  const double t1 = W * std::atan(1 / W) + H * std::atan(1 / H) - std::sqrt(S) * std::atan(1 / std::sqrt(S));
  const double g1 = (1 + W * W) * (1 + H * H) / (1 + S);
  const double g2 = W * W * (1 + S) / ((1 + W * W) * S);
  const double g3 = H * H * (1 + S) / ((1 + H * H) * S);
  const double t2 = 0.25 * (std::log(g1) + W * W * std::log(g2) + H * H * std::log(g3));
  steps.push_back("$W = w/l = " + num(W, 6) + "$, $H = h/l = " + num(H, 6) + "$.");
  steps.push_back(
      "Catalogue formula for perpendicular rectangles with a common edge: $F_{12} = \\frac{1}{\\pi W}"
      "\\big[W\\arctan\\frac1W + H\\arctan\\frac1H - \\sqrt{H^2+W^2}\\arctan\\frac{1}{\\sqrt{H^2+W^2}} "
      "+ \\frac14\\ln\\big(g_1\\, g_2^{W^2} g_3^{H^2}\\big)\\big]$ with $g_1 = \\frac{(1+W^2)(1+H^2)}"
      "{1+W^2+H^2}$, $g_2 = \\frac{W^2(1+W^2+H^2)}{(1+W^2)(W^2+H^2)}$, $g_3 = \\frac{H^2(1+W^2+H^2)}"
      "{(1+H^2)(W^2+H^2)}$.");
  steps.push_back("Arctangent part $" + num(t1, 6) + "$; $g_1 = " + num(g1, 6) + "$, $g_2 = " + num(g2, 6) +
                  "$, $g_3 = " + num(g3, 6) + "$; logarithm part $" + num(t2, 6) + "$.");
  return (t1 + t2) / (kPi * W);
}

// (1/A_i) int_{A_i} F(dA -> j) dA by Gauss-Legendre, graded towards the common edge (y = 0) where the
// integrand's derivative has a logarithmic singularity.
double integrateLambert(double l, double w, const Vec3& normal, const Polygon& to) {
  const QuadratureRule& rule = gaussLegendre(24);
  double sum = 0;
  for (std::size_t a = 0; a < rule.nodes.size(); ++a)
    for (std::size_t b = 0; b < rule.nodes.size(); ++b) {
      const double t = rule.nodes[b];
      const Vec3 x(l * rule.nodes[a], w * t * t, 0);
      sum += rule.weights[a] * rule.weights[b] * 2 * t * lambert(x, normal, to);
    }
  return sum;
}

}  // namespace rt::homework
