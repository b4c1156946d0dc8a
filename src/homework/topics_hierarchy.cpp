// A refinement decision of hierarchical radiosity (Hanrahan, Salzman and Aupperle 1991): a square node p on
// the floor gathers from a square node q on the ceiling. The oracle estimates each way's form factor from the
// centre of one node to the other treated as small, F_pq ~ A_q cos(theta_p) cos(theta_q) / (pi r^2), and
// links the pair when the larger estimate is below epsilon; otherwise it splits the node that looks larger
// from the other (the core's rule in refine/hierarchical_radiosity.cpp) and asks again for each child.
// Written from that estimate; the tests compare it with the core's point-to-polygon form factor of a shrunken
// node and with the core's splitting rule.
#include <array>
#include <cmath>
#include <numbers>

#include "homework/topics.h"

namespace rt::homework {
namespace {

// The small-node estimate between parallel facing nodes at the height h and the horizontal offset d.
double estimate(double area, double h, double d2) {
  const double r2 = h * h + d2;
  return area * h * h / (std::numbers::pi * r2 * r2);
}

}  // namespace

std::optional<Exercise> generateHierarchicalOracle(Draw& draw) {
  const double a = draw.value(0.4, 1.6, 0.1), b = draw.value(0.4, 1.6, 0.1);  // sides of p and q, m
  const double h = draw.value(1.5, 3.5, 0.1), x = draw.value(0, 2, 0.1);      // height, offset, m
  const double epsilon = draw.value(0.01, 0.08, 0.005);
  if (std::abs(a - b) < 0.2 * std::max(a, b)) return std::nullopt;  // which node splits must be clear
  const double Fpq = estimate(b * b, h, x * x), Fqp = estimate(a * a, h, x * x);
  const double error = std::max(Fpq, Fqp);
  if (error < 1.1 * epsilon) return std::nullopt;  // the pair itself must need refining
  const bool splitReceiver = Fqp >= Fpq;           // p looks larger from q than q from p
  const double side = splitReceiver ? a : b, other = splitReceiver ? b : a;
  // The four children, side/2, centres at (+-side/4, +-side/4) from the split node's centre; q sits at x.
  int linked = 0, linkedFar = 0;
  std::array<double, 4> childError{};
  for (int c = 0; c < 4; ++c) {
    const double dx = x - ((c & 1) ? side / 4 : -side / 4), dy = (c & 2) ? side / 4 : -side / 4;
    const double d2 = dx * dx + dy * dy;
    childError[c] = std::max(estimate(other * other, h, d2), estimate(side * side / 4, h, d2));
    if (std::abs(childError[c] - epsilon) < 0.03 * epsilon) return std::nullopt;  // too close to call
    linked += childError[c] < epsilon;
  }
  // The slip of using the parent's distance for every child.
  const double parentDistanceError =
      std::max(estimate(other * other, h, x * x), estimate(side * side / 4, h, x * x));
  linkedFar = parentDistanceError < epsilon ? 4 : 0;

  Exercise e;
  e.title = "A refinement decision of hierarchical radiosity";
  e.given = {{"a", a}, {"b", b}, {"height", h}, {"offset", x}, {"epsilon", epsilon}};
  e.statement =
      "Node $p$ is a square of side $a = " + num(a) +
      "$ m on the floor, facing up; node $q$ is a square of side $b = " + num(b) +
      "$ m on the ceiling $h = " + num(h) + "$ m above, facing down, its centre $x = " + num(x) +
      "$ m to the side of $p$'s (along an edge direction). The oracle estimates each form factor from the "
      "centre of one node to the other; the program uses Lambert's formula for the whole node, and by hand "
      "its small-node form will do, $\\hat F_{pq} = A_q \\cos\\theta_p "
      "\\cos\\theta_q / (\\pi r^2)$ with $r$ between the centres, and links the pair when "
      "$\\max(\\hat F_{pq}, \\hat F_{qp}) < \\varepsilon = " +
      num(epsilon) +
      "$. Otherwise it splits the node that looks larger from the other (the one with the larger estimate "
      "towards it) into four and asks again for each child with the other node. Find both estimates, which "
      "node is split (1 for $p$, 2 for $q$) and how many of its four children link at once.";
  e.hint =
      "Between parallel facing nodes $\\cos\\theta_p = \\cos\\theta_q = h/r$, so $\\hat F_{pq} = A_q h^2 / "
      "(\\pi "
      "r^4)$. Each child has its own centre: the quarter's centre is a quarter of the side from the "
      "parent's.";
  const double r2 = h * h + x * x;
  std::string children;
  for (int c = 0; c < 4; ++c)
    children += std::string(c ? ", " : "") + num(childError[c], 4) +
                (childError[c] < epsilon ? " (link)" : " (refine)");
  e.solution = {
      "$r^2 = h^2 + x^2 = " + num(r2, 6) +
          "$ m², $\\cos\\theta_p = \\cos\\theta_q = h/r = " + num(h / std::sqrt(r2), 6) + "$.",
      "$\\hat F_{pq} = b^2 h^2 / (\\pi r^4) = " + num(Fpq, 6) +
          "$ and $\\hat F_{qp} = a^2 h^2 / (\\pi r^4) = " + num(Fqp, 6) + "$; the larger, " + num(error, 6) +
          ", is not below $\\varepsilon = " + num(epsilon) + "$, so the pair is refined.",
      std::string("The larger estimate is ") +
          (splitReceiver ? "$\\hat F_{qp}$: $p$ looks larger from $q$, so $p$"
                         : "$\\hat F_{pq}$: $q$ looks larger from $p$, so $q$") +
          " is split into four squares of side " + num(side / 2) + " m.",
      "The children's larger estimates, each from its own centre: " + children + ". So " +
          (linked == 4 ? std::string("all four link at this level.")
           : linked == 0
               ? std::string("none links yet: each child is refined further.")
               : std::to_string(linked) + " of the four link at this level; the others are refined further."),
  };
  e.questions = {
      {"Fpq",
       "$\\hat F_{pq}$",
       Fpq,
       tolerance(Fpq, 0.002, 1e-7),
       false,
       {{"the cosines left out (A_q / (pi r^2))", b * b / (std::numbers::pi * r2)},
        {"the receiver's area used (that is F_qp)", Fqp},
        {"the height used for r (the offset ignored)", b * b / (std::numbers::pi * h * h)}}},
      {"Fqp",
       "$\\hat F_{qp}$",
       Fqp,
       tolerance(Fqp, 0.002, 1e-7),
       false,
       {{"the cosines left out", a * a / (std::numbers::pi * r2)},
        {"the source's area used (that is F_pq)", Fpq}}},
      {"split", "the node split (1 = $p$, 2 = $q$)", splitReceiver ? 1.0 : 2.0, 0.5, true, {}},
      {"linked",
       "children linked at once (0 to 4)",
       static_cast<double>(linked),
       0.5,
       true,
       {{"the parent's centre used for every child", static_cast<double>(linkedFar)}}},
  };
  return e;
}

}  // namespace rt::homework
