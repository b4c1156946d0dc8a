// Evaluating a linear element by hand: a rectangular element with radiosities at its four corners, the
// bilinear shape functions at a point, the radiosity there, the element's average (what a constant element
// would hold) and the integral of one corner's shape function (that node's share of the element, its weight
// in the Galerkin system). Computed here from the shape functions' definitions (Cohen and Wallace 1993,
// ch. 3), not from the core's basis, which the tests compare it with.
#include <cmath>

#include "homework/topics.h"

namespace rt::homework {

std::optional<Exercise> generateLinearElement(Draw& draw) {
  const double a = draw.value(0.2, 1.0, 0.1), b = draw.value(0.2, 1.0, 0.1);  // the sides, m
  Eigen::VectorXd B(4);
  for (int k = 0; k < 4; ++k) B[k] = draw.value(5, 60, 1);  // W/m^2 at corners 1..4
  const double x = draw.value(0.1, 0.9, 0.05) * a, y = draw.value(0.1, 0.9, 0.05) * b;
  const int asked = draw.integer(0, 3);
  const double u = x / a, v = y / b;
  // Corners counter-clockwise from the origin: (0,0), (a,0), (a,b), (0,b).
  const auto shapes = [](double s, double t) {
    Eigen::VectorXd phi(4);
    phi << (1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t;
    return phi;
  };
  const Eigen::VectorXd phi = shapes(u, v), swapped = shapes(v, u);
  const double value = phi.dot(B), average = B.mean(), weight = a * b / 4;
  // A draw whose slips land on the answer cannot tell them apart: skip it.
  if (std::abs(swapped.dot(B) - value) < 0.5 || std::abs(average - value) < 0.5) return std::nullopt;
  int nearest = 0;
  const double cx[4] = {0, a, a, 0}, cy[4] = {0, 0, b, b};
  for (int k = 1; k < 4; ++k)
    if (std::hypot(x - cx[k], y - cy[k]) < std::hypot(x - cx[nearest], y - cy[nearest])) nearest = k;
  if (std::abs(B[nearest] - value) < 0.5) return std::nullopt;
  const std::string c = std::to_string(asked + 1);

  Exercise e;
  e.title = "Evaluating a linear element";
  e.given = {{"a", a}, {"b", b}, {"x", x}, {"y", y}, {"asked", asked + 1}};
  for (int k = 0; k < 4; ++k) e.given["b" + std::to_string(k + 1)] = B[k];
  e.statement =
      "A rectangular element of a linear basis has the corners $1 = (0, 0)$, $2 = (" + num(a) +
      ", 0)$, $3 = (" + num(a) + ", " + num(b) + ")$ and $4 = (0, " + num(b) +
      ")$ (metres, in the element's plane). The "
      "solved radiosities at the corners are $b = " +
      vectorLatex(B, 4) +
      "$ W/m². The radiosity inside is the bilinear interpolation $B(x, y) = \\sum_k b_k \\varphi_k(u, v)$ "
      "with $u = x / a$, $v = y / b$, $\\varphi_1 = (1-u)(1-v)$, $\\varphi_2 = u(1-v)$, $\\varphi_3 = uv$, "
      "$\\varphi_4 = (1-u)v$. At the point $(" +
      num(x) + ", " + num(y) + ")$ find (a) $\\varphi_" + c +
      "$, (b) $B$, (c) the element's average radiosity $\\frac{1}{A}\\int B\\,dA$ and (d) $\\int \\varphi_" +
      c + "\\,dA$ over the element.";
  e.hint =
      "Each shape function is 1 at its own corner and 0 at the other three, and they add up to 1 everywhere. "
      "On a rectangle $\\int \\varphi_k\\,dA = ab \\int_0^1\\!\\int_0^1 \\varphi_k\\,du\\,dv$.";
  e.solution = {
      "$u = " + num(x) + " / " + num(a) + " = " + num(u, 6) + "$, $v = " + num(y) + " / " + num(b) + " = " +
          num(v, 6) + "$.",
      "The shape functions there: $\\varphi = " + vectorLatex(phi, 6) +
          "$ (they add up to 1), so $\\varphi_" + c + " = " + num(phi[asked], 6) + "$.",
      "$B = \\sum_k b_k \\varphi_k = " + num(value, 6) + "$ W/m².",
      "Each $\\varphi_k$ integrates to $ab/4$ over the rectangle, so the average is the mean of the corners: "
      "$\\bar B = " +
          num(average, 6) + "$ W/m², the value a constant element would hold.",
      "$\\int \\varphi_" + c + "\\,dA = ab/4 = " + num(a) + " \\times " + num(b) +
          " / 4 = " + num(weight, 6) + "$ m²: this element's part of node " + c + "'s weight $A_v$.",
  };
  e.questions = {
      {"phi",
       "(a) $\\varphi_" + c + "$ at the point",
       phi[asked],
       tolerance(phi[asked], 0.002, 1e-4),
       false,
       {{"u and v swapped (x measured along b)", swapped[asked]},
        {"the opposite corner's shape function", phi[(asked + 2) % 4]}}},
      {"B",
       "(b) $B$ at the point, W/m²",
       value,
       tolerance(value, 0.002, 1e-3),
       false,
       {{"u and v swapped (x measured along b)", swapped.dot(B)},
        {"the element's average: the constant basis's value, not the linear one's", average},
        {"the nearest corner's value", B[nearest]}}},
      {"average",
       "(c) the element's average radiosity, W/m²",
       average,
       tolerance(average, 0.002, 1e-3),
       false,
       {{"the corners summed, not averaged", B.sum()}, {"the value at the point", value}}},
      {"weight",
       "(d) $\\int \\varphi_" + c + "\\,dA$, m²",
       weight,
       tolerance(weight, 0.002, 1e-6),
       false,
       {{"the whole element's area", a * b}, {"half the area", a * b / 2}}},
  };
  return e;
}

}  // namespace rt::homework
