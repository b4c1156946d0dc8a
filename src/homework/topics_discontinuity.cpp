// The critical lines of a shadow (Heckbert 1992; Lischinski, Tampieri and Greenberg 1992): a strip light on
// the ceiling, a table top below it and the floor, all long along y, seen in the cross-section through their
// middle. The rays from each long edge of the light through each long edge of the table meet the floor on the
// four critical lines that bound the umbra and the two penumbrae; a discontinuity mesh makes them element
// edges. The edges are parallel, so the hidden part of the light grows as a strip: the lines are D1. The key
// is computed here by similar triangles; the tests compare the lines with the core's critical segments of the
// scene file handed out with the exercise, and the visible width with rays traced forwards from the point.
#include <algorithm>
#include <array>
#include <cmath>

#include "homework/scene_text.h"
#include "homework/topics.h"

namespace rt::homework {
namespace {

// Where the ray from the light's edge l (height H) through the table's edge o (height h) meets the floor.
double floorLine(double l, double o, double scale) {
  return l + (o - l) * scale;
}

}  // namespace

std::optional<Exercise> generateDiscontinuity(Draw& draw) {
  const double H = draw.value(2.4, 3.2, 0.1), h = draw.value(0.6, 1.2, 0.05);
  const double l0 = draw.value(-0.4, 0.2, 0.05), w = draw.value(0.2, 0.6, 0.05);
  const double o0 = draw.value(-0.8, 0.2, 0.05), d = draw.value(0.6, 1.2, 0.05);
  const double l1 = l0 + w, o1 = o0 + d, k = H / (H - h);
  // The lines from left to right: the outer and inner edges of the left penumbra, then the right one's.
  const std::array<double, 4> x{floorLine(l1, o0, k), floorLine(l0, o0, k), floorLine(l1, o1, k),
                                floorLine(l0, o1, k)};
  if (x[2] - x[1] < 0.1) return std::nullopt;  // an umbra that the reader can see
  // The point lies inside one penumbra, away from its edges.
  const bool left = draw.integer(0, 1) == 0;
  const double from = left ? x[0] : x[2], to = left ? x[1] : x[3];
  const double xp = std::round(100 * (from + draw.value(0.2, 0.8, 0.05) * (to - from))) / 100;
  if (xp < from + 0.02 || xp > to - 0.02) return std::nullopt;
  // From the point, the table hides the part of the light plane between the table edges' back-projections.
  const double p0 = floorLine(xp, o0, H / h), p1 = floorLine(xp, o1, H / h);
  const double hidden = std::max(0.0, std::min(l1, p1) - std::max(l0, p0));
  const double visible = w - hidden;
  const double q0 = floorLine(xp, o0, k), q1 = floorLine(xp, o1, k);  // the slip: H - h for h
  const double visibleSlip = w - std::max(0.0, std::min(l1, q1) - std::max(l0, q0));
  // A floor element of a uniform mesh, and the critical lines that cross it.
  const double side = draw.value(0.2, 0.6, 0.1), e0 = draw.value(x[0] - 0.4, x[3] + 0.1, 0.05);
  int crossing = 0;
  for (const double line : x) {
    if (std::abs(line - e0) < 0.01 || std::abs(line - e0 - side) < 0.01) return std::nullopt;
    crossing += line > e0 && line < e0 + side;
  }
  const double c = (l0 + l1) / 2;  // the light's centre: the point-light slip's shadow edges
  const std::array<double, 2> pointEdges{floorLine(c, o0, k), floorLine(c, o1, k)};
  int crossingPoint = 0;
  for (const double line : pointEdges) crossingPoint += line > e0 && line < e0 + side;

  Exercise e;
  e.title = "The critical lines of a table's shadow";
  e.given = {{"H", H},   {"h", h},   {"l0", l0}, {"l1", l1},       {"o0", o0},
             {"o1", o1}, {"xp", xp}, {"e0", e0}, {"e1", e0 + side}};
  e.statement =
      "A strip light on the ceiling, at the height $H = " + num(H) + "$ m, spans $" + num(l0) +
      " \\le x \\le " + num(l1) + "$ m and faces down. A table top at the height $h = " + num(h) +
      "$ m spans $" + num(o0) + " \\le x \\le " + num(o1) +
      "$ m. Both are long along $y$, their long edges parallel; take the cross-section "
      "$y = 0$ through their middle, far from their ends. On the floor, $z = 0$, the shadow of the table has "
      "an umbra between two penumbrae. Find (a) the four critical lines $x_1 < x_2 < x_3 < x_4$ where the "
      "rays from the light's long edges through the table's long edges meet the floor, (b) the width of the "
      "light that the floor point $x = " +
      num(xp) +
      "$ m sees, (c) the order $k$ of the discontinuity ($D^k$) of the radiosity across these "
      "lines, and (d) how many of them cross the floor element $" +
      num(e0) + " \\le x \\le " + num(e0 + side) + "$ m, which a discontinuity mesh would cut there.";
  e.hint =
      "Similar triangles: the ray from the light's edge $l$ through the table's edge $o$ drops $H - h$ to "
      "reach the table and $H$ to reach the floor, so it meets the floor at $l + (o - l)\\,H / (H - h)$. "
      "From a floor point, project the table's edges up onto the ceiling the same way, with $h$ in place "
      "of $H - h$.";
  std::string lines;
  const char* names[4] = {"x_1", "x_2", "x_3", "x_4"};
  const double edgeL[4] = {l1, l0, l1, l0}, edgeO[4] = {o0, o0, o1, o1};
  for (int i = 0; i < 4; ++i)
    lines += std::string(i ? ", " : "") + "$" + names[i] + " = " + num(edgeL[i]) + " + (" + num(edgeO[i]) +
             " - " + num(edgeL[i]) + ") \\times " + num(k, 6) + " = " + num(x[i], 6) + "$";
  e.solution = {
      "$H / (H - h) = " + num(H) + " / " + num(H - h) + " = " + num(k, 6) +
          "$. The left penumbra runs from the ray through the table's left edge from the light's right edge "
          "to the one from its left edge; the right penumbra likewise: " +
          lines + " m.",
      "The umbra is $" + num(x[1], 6) + " < x < " + num(x[2], 6) + "$; each penumbra is $w h / (H - h) = " +
          num(w) + " \\times " + num(h) + " / " + num(H - h) + " = " + num(x[1] - x[0], 6) + "$ m wide.",
      "From $x = " + num(xp) + "$ the table's edges project onto the ceiling at $x + (o - x)\\,H / h$: $" +
          num(p0, 6) + "$ and $" + num(p1, 6) + "$. The light $[" + num(l0) + ", " + num(l1) +
          "]$ loses the overlap, " + num(hidden, 6) + " m, so " + num(visible, 6) + " m of its " + num(w) +
          " m are seen.",
      "The table's long edges are parallel to the light's, so crossing a line the hidden part of the light "
      "is a strip whose width grows in proportion to the distance: the irradiance has a kink there, its "
      "first derivative jumps: $D^1$. (Edges that are not parallel give $D^2$; a contact or a point light "
      "$D^0$.)",
      "The element $[" + num(e0) + ", " + num(e0 + side) + "]$ contains " + std::to_string(crossing) +
          " of the four lines.",
  };
  e.questions.reserve(7);
  for (int i = 0; i < 4; ++i) {
    const double scaleSlip = floorLine(edgeL[i], edgeO[i], 1 + h / H);  // h / H for h / (H - h)
    e.questions.push_back(
        {"x" + std::to_string(i + 1),
         "(a) $" + std::string(names[i]) + "$, m",
         x[i],
         tolerance(x[i], 0.002, 0.002),
         false,
         {{"the offset past the table scaled by h / H, not h / (H - h)", scaleSlip},
          {"the light taken as a point at its centre (the hard shadow's edge)", pointEdges[i / 2]}}});
  }
  e.questions.push_back({"visible",
                         "(b) the width of the light seen from the point, m",
                         visible,
                         tolerance(visible, 0.002, 0.002),
                         false,
                         {{"the hidden width given", hidden},
                          {"projected with H / (H - h), the table's edges cast onto the floor", visibleSlip},
                          {"the fraction of the light seen, not its width", visible / w}}});
  e.questions.push_back({"order",
                         "(c) the order $k$ of the discontinuity",
                         1,
                         0.5,
                         true,
                         {{"D2 is the order of lines from edges that are not parallel", 2},
                          {"D0 is the order at a contact or for a point light", 0}}});
  e.questions.push_back(
      {"crossing",
       "(d) critical lines crossing the element",
       static_cast<double>(crossing),
       0.5,
       true,
       {{"only the point light's two shadow edges counted", static_cast<double>(crossingPoint)}}});

  const double Ll = 1.0, Lo = 1.5, F = 4.0;  // half-lengths along y; the floor's half-size
  e.sceneJson = sceneJsonText("A table's shadow",
                              {{"floor", {{-F, -F, 0}, {F, -F, 0}, {F, F, 0}, {-F, F, 0}}, 0.5, 0},
                               {"light", {{l0, -Ll, H}, {l0, Ll, H}, {l1, Ll, H}, {l1, -Ll, H}}, 0, 10},
                               {"table", {{o0, -Lo, h}, {o1, -Lo, h}, {o1, Lo, h}, {o0, Lo, h}}, 0.5, 0}});
  Figure fig;
  fig.line({x[0] - 0.3, 0}, {x[3] + 0.3, 0});
  fig.rect({l0, H}, {l1, H + 0.06}, "accent");
  fig.rect({o0, h - 0.03}, {o1, h}, "grey");
  fig.line({xp, 0}, {xp, 0.15});
  fig.label({xp, 0.3}, "x = " + num(xp));
  fig.rect({e0, -0.06}, {e0 + side, 0}, "light");
  fig.label({(l0 + l1) / 2, H + 0.25}, "light");
  fig.label({(o0 + o1) / 2, h + 0.2}, "table");
  fig.label({x[0] - 0.1, 0.2}, "floor");
  fig.label({e0 + side / 2, -0.25}, "element");
  fig.caption = "The cross-section y = 0 (metres; the element on the floor shaded).";
  e.figure = fig;
  return e;
}

}  // namespace rt::homework
