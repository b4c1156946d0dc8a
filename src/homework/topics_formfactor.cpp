// Form factors by hand: two rectangles from the catalogue formulas (parallel, perpendicular) or by
// integrating Lambert's point-to-polygon formula over the source (at an angle), and the Nusselt analog for a
// small patch. The keys are computed here from the textbook formulas; the tests compare them with the core's
// contour integral and Nusselt projection, which share no code with them.
#include <cmath>
#include <numbers>

#include "homework/catalogue.h"
#include "homework/scene_text.h"
#include "homework/topics.h"

namespace rt::homework {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

std::optional<Exercise> generateRectangles(Draw& draw) {
  Exercise e;
  e.title = "Form factor between two rectangles";
  const int kind = draw.integer(0, 2);
  Polygon pi, pj;
  std::vector<std::string>& s = e.solution;
  double F12 = 0, Ai = 0, Aj = 0, rel = 0.005;
  Figure fig;
  if (kind == 0) {
    const double a = draw.value(0.5, 3, 0.1), b = draw.value(0.5, 3, 0.1), c = draw.value(0.5, 2.5, 0.1);
    pi = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}};
    pj = {{0, 0, c}, {0, b, c}, {a, b, c}, {a, 0, c}};
    Ai = Aj = a * b;
    e.statement = "Two rectangles of $" + num(a) + " \\times " + num(b) +
                  "$ m face each other, directly opposed, at "
                  "a distance $c = " +
                  num(c) + "$ m (rectangle 1 at $z = 0$ facing up, rectangle 2 at $z = " + num(c) +
                  "$ facing down).";
    F12 = parallelRectangles(a, b, c, s);
    fig.line({0, 0}, {a, 0});
    fig.line({0, c}, {a, c});
    fig.label({a / 2, -0.18 * c}, "1 (a = " + num(a) + ")");
    fig.label({a / 2, 1.12 * c}, "2");
    fig.line({a + 0.1, 0}, {a + 0.1, c}, true);
    fig.label({a + 0.3, c / 2}, "c = " + num(c));
  } else {
    const double l = draw.value(0.5, 3, 0.1), w = draw.value(0.5, 3, 0.1), h = draw.value(0.5, 3, 0.1);
    const double phi = kind == 1 ? 90.0 : draw.value(35, 145, 5);
    if (kind == 2 && std::abs(phi - 90) < 1) return std::nullopt;  // that is the perpendicular variant
    const double r = phi * kPi / 180;
    const Vec3 d(0, std::cos(r), std::sin(r));
    pi = {{0, 0, 0}, {l, 0, 0}, {l, w, 0}, {0, w, 0}};
    pj = {{0, 0, 0}, {0, h * d.y(), h * d.z()}, {l, h * d.y(), h * d.z()}, {l, 0, 0}};
    Ai = l * w;
    Aj = l * h;
    e.statement = "Rectangle 1 ($" + num(l) + " \\times " + num(w) +
                  "$ m) lies on the floor; rectangle 2 ($" + num(l) + " \\times " + num(h) +
                  "$ m) shares its edge of length $l = " + num(l) + "$ m and rises from it at an angle of $" +
                  num(phi) +
                  "^\\circ$ between the two (measured inside "
                  "the wedge they form, where both fronts face).";
    if (kind == 1) {
      F12 = perpendicularRectangles(w, h, l, s);
    } else {
      rel = 0.01;
      F12 = integrateLambert(l, w, Vec3(0, 0, 1), pj);
      const double centre = lambert(Vec3(l / 2, w / 2, 0), Vec3(0, 0, 1), pj);
      s.push_back(
          "No short catalogue formula: integrate Lambert's formula $F_{dA\\to 2} = \\frac{1}{2\\pi}"
          "\\sum_k \\beta_k \\cos\\gamma_k$ ($\\beta_k$ the angle edge $k$ of rectangle 2 subtends at the "
          "point, $\\gamma_k$ the angle between rectangle 1's normal and that of the plane through the point "
          "and edge $k$) over rectangle 1, $F_{12} = \\frac{1}{A_1}\\int_{A_1} "
          "F_{dA\\to 2}\\,dA$ (e.g. Gauss-Legendre, with nodes crowded towards the common edge).");
      s.push_back("At the centre of rectangle 1, $F_{dA\\to 2} = " + num(centre, 6) +
                  "$; the integral (24 x 24 Gauss-Legendre nodes) gives the mean over the rectangle.");
    }
    fig.line({0, 0}, {w, 0});
    fig.line({0, 0}, {h * d.y(), h * d.z()});
    fig.label({w / 2, -0.25}, "1 (w = " + num(w) + ")");
    fig.label({h * d.y(), h * d.z() + 0.15 * std::max(w, h)}, "2 (h = " + num(h) + ")");
    fig.label({0.35 * std::cos(r / 2), 0.35 * std::sin(r / 2)}, num(phi) + " deg");
    fig.caption = "Seen along the common edge (length " + num(l) + " m).";
  }
  if (!(F12 > 0.02 && F12 < 0.98)) return std::nullopt;  // too small to read, or all but 1
  const double F21 = Ai * F12 / Aj;
  s.push_back("$F_{12} = " + num(F12, 6) + "$.");
  s.push_back("Reciprocity $A_1 F_{12} = A_2 F_{21}$: $F_{21} = \\frac{" + num(Ai, 6) + " \\times " +
              num(F12, 6) + "}{" + num(Aj, 6) + "} = " + num(F21, 6) + "$.");
  e.statement += " Compute $F_{12}$ (rectangle 1 to 2) and $F_{21}$.";
  e.hint =
      "Find the matching catalogue configuration, compute the dimensionless ratios first, then use "
      "reciprocity $A_1F_{12} = A_2F_{21}$ for the second.";
  Question q1{"F12", "$F_{12}$", F12, tolerance(F12, rel, 1e-4), false, {{"F_21 given for F_12", F21}}};
  Question q2{"F21",
              "$F_{21}$",
              F21,
              tolerance(F21, rel, 1e-4),
              false,
              {{"F_12 given for F_21 (reciprocity not applied)", F12},
               {"areas swapped in reciprocity (A_2 F_12 / A_1)", Aj * F12 / Ai}}};
  e.questions = {q1, q2};
  fig.caption = fig.caption.empty() ? "Side view." : fig.caption;
  e.figure = fig;
  const std::vector<NamedPolygon> surfaces{{"rectangle-1", pi}, {"rectangle-2", pj}};
  e.sceneJson = sceneJsonText("Two rectangles", surfaces);
  e.sceneObj = sceneObjText(surfaces);
  return e;
}

std::optional<Exercise> generateNusselt(Draw& draw) {
  Exercise e;
  e.title = "The Nusselt analog";
  const double h = draw.value(0.5, 2, 0.1);
  const double x0 = draw.value(-1.5, 1.0, 0.1), y0 = draw.value(-1.5, 1.0, 0.1);
  const double x1 = x0 + draw.value(0.4, 2, 0.1), y1 = y0 + draw.value(0.4, 2, 0.1);
  // Seen from below, counter-clockwise: the rectangle faces the patch.
  const Polygon p{{x0, y0, h}, {x0, y1, h}, {x1, y1, h}, {x1, y0, h}};
  const Vec3 n(0, 0, 1);
  std::vector<std::string>& s = e.solution;
  s.push_back(
      "Project each corner onto the unit hemisphere, $\\hat R_k = R_k/|R_k|$; dropping it onto the base "
      "disk keeps its $(x, y)$. For Lambert's sum, edge $k$ runs from corner $k$ to corner $k+1$: "
      "$\\beta_k$ is the angle it subtends at the patch, and $\\cos\\gamma_k = \\pm\\, n \\cdot "
      "\\frac{R_k \\times R_{k+1}}{|R_k \\times R_{k+1}|}$, the cosine of the angle between $n$ and the "
      "normal of the plane through the patch and the edge (one sign for all edges, the one that makes the "
      "sum positive: it depends on the order of the corners).");
  // cos gamma_k carries a sign: an edge seen "backwards" (the zenith outside the polygon) takes area away.
  // The polygon's orientation fixes the overall sign, made positive afterwards.
  std::vector<double> betas, cosines;
  double signedSum = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec3 a = p[k].normalized(), b = p[(k + 1) % p.size()].normalized();
    const Vec3 c = a.cross(b);
    betas.push_back(std::atan2(c.norm(), a.dot(b)));
    cosines.push_back(n.dot(c.normalized()));
    signedSum += betas.back() * cosines.back();
  }
  const double orientation = signedSum < 0 ? -1 : 1;
  const double sum = std::abs(signedSum), beta1 = betas[0];
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec3 a = p[k].normalized();
    const double cosGamma = orientation * cosines[k], beta = betas[k];
    s.push_back("Corner " + std::to_string(k + 1) + ": $\\hat R = " + vectorLatex(a, 5) + "$, disk point $(" +
                num(a.x(), 5) + ", " + num(a.y(), 5) + ")$; edge " + std::to_string(k + 1) + ": $\\beta_" +
                std::to_string(k + 1) + " = " + num(beta, 6) + "$ rad, $\\cos\\gamma_" +
                std::to_string(k + 1) + " = " + num(cosGamma, 6) + "$, term $" + num(beta * cosGamma, 6) +
                "$.");
  }
  const double F = sum / (2 * kPi);
  if (!(F > 0.02)) return std::nullopt;
  s.push_back("$F = \\frac{1}{2\\pi}\\sum_k \\beta_k\\cos\\gamma_k = \\frac{" + num(sum, 6) +
              "}{2\\pi} = " + num(F, 6) + "$.");
  s.push_back("Nusselt: the projection covers $\\pi F = " + num(kPi * F, 6) +
              "$ of the unit disk's area $\\pi$.");
  e.statement =
      "A small patch at the origin faces up ($n = (0, 0, 1)$). A rectangle with corners $(" + num(x0) + ", " +
      num(y0) + ")$ and $(" + num(x1) + ", " + num(y1) + ")$ in $x, y$ lies in the plane $z = " + num(h) +
      "$, facing down. Using the Nusselt analog (project onto the unit hemisphere, then onto the base "
      "disk), find $\\beta_1$, the angle the edge from corner $(" +
      num(x0) + ", " + num(y0) + ")$ to $(" + num(x0) + ", " + num(y1) +
      ")$ subtends at the patch, the area of the projected region on the disk, "
      "and the form factor $F_{dA \\to 2}$.";
  e.hint =
      "The form factor is the projected area divided by the disk's area $\\pi$; Lambert's formula "
      "$F = \\frac{1}{2\\pi}\\sum_k\\beta_k\\cos\\gamma_k$ computes the same area edge by edge ($\\beta_k$ "
      "the angle edge $k$ subtends at the patch, $\\gamma_k$ the angle between the patch's normal and the "
      "normal of the plane through the patch and edge $k$).";
  e.questions = {
      {"beta1",
       "$\\beta_1$ in radians",
       beta1,
       tolerance(beta1, 0.002, 1e-4),
       false,
       {{"angle given in degrees, not radians", beta1 * 180 / kPi}}},
      {"disk",
       "projected area on the unit disk",
       kPi * F,
       tolerance(kPi * F, 0.005, 1e-4),
       false,
       {{"form factor given for the disk area (not multiplied by pi)", F}}},
      {"F",
       "$F_{dA\\to 2}$",
       F,
       tolerance(F, 0.005, 1e-4),
       false,
       {{"disk area given for F (not divided by the disk's area pi)", kPi * F},
        {"divided by 2 pi twice or by the hemisphere's area", F / 2}}},
  };
  Figure fig;
  std::vector<Vec2> disk;
  for (int k = 0; k <= 64; ++k) disk.emplace_back(std::cos(2 * kPi * k / 64), std::sin(2 * kPi * k / 64));
  fig.shapes.push_back({disk, true, "light", false});
  std::vector<Vec2> outline;
  for (std::size_t k = 0; k < p.size(); ++k)
    for (int t = 0; t < 16; ++t) {
      const Vec3 q = (p[k] + (p[(k + 1) % p.size()] - p[k]) * (t / 16.0)).normalized();
      outline.emplace_back(q.x(), q.y());
    }
  fig.shapes.push_back({outline, true, "accent", false});
  fig.label({0, -1.15}, "unit disk");
  fig.caption = "The rectangle's projection on the base disk (Nusselt analog).";
  e.figure = fig;
  const double d = 0.02;
  const std::vector<NamedPolygon> surfaces{{"patch", {{-d, -d, 0}, {d, -d, 0}, {d, d, 0}, {-d, d, 0}}},
                                           {"rectangle", p}};
  e.sceneJson = sceneJsonText("Nusselt analog", surfaces);
  e.sceneObj = sceneObjText(surfaces);
  return e;
}

}  // namespace rt::homework
