// Enclosures: reciprocity and closure in a box, and the matrix K of a duct. The given form factors are
// rounded as printed; every answer follows from exactly those numbers.
#include <cmath>

#include "homework/catalogue.h"
#include "homework/duct.h"
#include "homework/scene_text.h"
#include "homework/topics.h"

namespace rt::homework {
namespace {

double round4(double x) {
  return std::round(x * 1e4) / 1e4;
}

}  // namespace

std::optional<Exercise> generateClosure(Draw& draw) {
  const double X = draw.value(1, 4, 0.5), Y = draw.value(1, 4, 0.5), Z = draw.value(1, 3, 0.5);
  if (std::abs(X - Y) < 0.4 || std::abs(X - Z) < 0.4 || std::abs(Y - Z) < 0.4) return std::nullopt;
  std::vector<std::string> unused;
  const double F12 = round4(parallelRectangles(X, Y, Z, unused));
  const double F13 = round4(perpendicularRectangles(X, Z, Y, unused));
  const double F34 = round4(parallelRectangles(Y, Z, X, unused));
  const double A1 = X * Y, A3 = Y * Z, A5 = X * Z;
  const double F15 = (1 - F12 - 2 * F13) / 2;
  const double F51 = A1 * F15 / A5, F31 = A1 * F13 / A3;
  const double F35 = (1 - F34 - 2 * F31) / 2;
  if (!(F15 > 0.02 && F35 > 0.02)) return std::nullopt;
  Exercise e;
  e.title = "Reciprocity and closure in a box";
  e.statement =
      "A closed box is $" + num(X) + "$ m wide ($x$), $" + num(Y) + "$ m deep ($y$) and $" + num(Z) +
      "$ m high ($z$). Its six faces: 1 floor, 2 ceiling, 3 and 4 the walls at $x = 0$ and $x = " + num(X) +
      "$, 5 and 6 the walls at $y = 0$ and $y = " + num(Y) + "$. Given $F_{12} = " + num(F12) +
      "$, $F_{13} = " + num(F13) + "$ and $F_{34} = " + num(F34) +
      "$, use only symmetry, reciprocity and closure (no further catalogue formula) to find $F_{15}$, "
      "$F_{51}$, "
      "$F_{31}$ and $F_{35}$.";
  e.hint =
      "Every row of F sums to 1 in a closed room ($F_{ii} = 0$ for flat faces); by symmetry $F_{14} = "
      "F_{13}$ "
      "and $F_{16} = F_{15}$; reciprocity: $A_iF_{ij} = A_jF_{ji}$.";
  auto& s = e.solution;
  s.push_back("Areas: $A_1 = A_2 = " + num(A1) + "$, $A_3 = A_4 = " + num(A3) + "$, $A_5 = A_6 = " + num(A5) +
              "$ $\\mathrm{m}^2$.");
  s.push_back("Row 1: $F_{12} + 2F_{13} + 2F_{15} = 1$, so $F_{15} = (1 - " + num(F12) + " - 2 \\times " +
              num(F13) + ")/2 = " + num(F15, 6) + "$.");
  s.push_back("Reciprocity: $F_{51} = A_1F_{15}/A_5 = " + num(A1) + " \\times " + num(F15, 6) + " / " +
              num(A5) + " = " + num(F51, 6) + "$.");
  s.push_back("Reciprocity: $F_{31} = A_1F_{13}/A_3 = " + num(A1) + " \\times " + num(F13) + " / " + num(A3) +
              " = " + num(F31, 6) + "$.");
  s.push_back(
      "Row 3: $F_{31} + F_{32} + F_{34} + F_{35} + F_{36} = 1$ with $F_{32} = F_{31}$ and $F_{36} = "
      "F_{35}$: $F_{35} = (1 - " +
      num(F34) + " - 2 \\times " + num(F31, 6) + ")/2 = " + num(F35, 6) + "$.");
  const double t = 1.5e-4;
  e.questions = {
      {"F15",
       "$F_{15}$",
       F15,
       tolerance(F15, 0.002, t),
       false,
       {{"symmetry forgotten: the rest of row 1 given to one wall", 1 - F12 - 2 * F13}}},
      {"F51",
       "$F_{51}$",
       F51,
       tolerance(F51, 0.002, t),
       false,
       {{"F_15 given for F_51 (reciprocity not applied)", F15},
        {"areas swapped in reciprocity (A_5 F_15 / A_1)", A5 * F15 / A1}}},
      {"F31",
       "$F_{31}$",
       F31,
       tolerance(F31, 0.002, t),
       false,
       {{"F_13 given for F_31 (reciprocity not applied)", F13},
        {"areas swapped in reciprocity (A_3 F_13 / A_1)", A3 * F13 / A1}}},
      {"F35",
       "$F_{35}$",
       F35,
       tolerance(F35, 0.002, t),
       false,
       {{"F_13 used for F_31 in the closure of row 3", (1 - F34 - 2 * F13) / 2}}},
  };
  e.rowChecks = {{"row 1 (the floor)", {{"F15", 2}}, F12 + 2 * F13},
                 {"row 3 (the wall at x = 0)", {{"F31", 2}, {"F35", 2}}, F34}};
  Figure f;
  f.rect({0, 0}, {X, Y}, "light");
  f.label({X / 2, Y / 2}, "1 floor (2 above)");
  f.label({-0.25, Y / 2}, "3");
  f.label({X + 0.25, Y / 2}, "4");
  f.label({X / 2, -0.25}, "5");
  f.label({X / 2, Y + 0.25}, "6");
  f.caption = "Plan of the box (z up).";
  e.figure = f;
  const std::vector<NamedPolygon> faces{
      {"floor", {{0, 0, 0}, {X, 0, 0}, {X, Y, 0}, {0, Y, 0}}},
      {"ceiling", {{0, 0, Z}, {0, Y, Z}, {X, Y, Z}, {X, 0, Z}}},
      {"wall-x0", {{0, 0, 0}, {0, Y, 0}, {0, Y, Z}, {0, 0, Z}}},
      {"wall-x1", {{X, 0, 0}, {X, 0, Z}, {X, Y, Z}, {X, Y, 0}}},
      {"wall-y0", {{0, 0, 0}, {0, 0, Z}, {X, 0, Z}, {X, 0, 0}}},
      {"wall-y1", {{0, Y, 0}, {X, Y, 0}, {X, Y, Z}, {0, Y, Z}}},
  };
  e.sceneJson = sceneJsonText("Closed box", faces);
  e.sceneObj = sceneObjText(faces);
  return e;
}

std::optional<Exercise> generateAssembleK(Draw& draw) {
  const int n = draw.integer(3, 5);
  std::optional<Duct> d = drawDuct(draw, n);
  if (!d) return std::nullopt;
  const Eigen::MatrixXd K = ductK(*d);
  // Well-posed: rho < 1 keeps K strictly diagonally dominant by columns of rho F's row sums; check anyway.
  if (d->rho.maxCoeff() >= 1 || K.fullPivLu().rank() < n) return std::nullopt;
  Exercise e;
  e.title = "Assembling K";
  e.statement =
      ductStatement(*d) + " Assemble $K = I - \\operatorname{diag}(\\rho)F$, the matrix of $KB = E$.";
  e.hint = "Row $i$ of $K$ is row $i$ of $F$ times $-\\rho_i$, plus 1 on the diagonal ($F_{ii} = 0$).";
  for (int i = 0; i < n; ++i) {
    std::string row = "Row " + std::to_string(i + 1) + ": $\\rho_" + std::to_string(i + 1) + " = " +
                      num(d->rho[i]) + "$, so $K_{" + std::to_string(i + 1) + "j} = \\delta_{" +
                      std::to_string(i + 1) + "j} - " + num(d->rho[i]) + " F_{" + std::to_string(i + 1) +
                      "j}$: ";
    for (int j = 0; j < n; ++j) {
      row += (j ? ", " : "") + num(K(i, j), 6);
      const std::string id = "K" + std::to_string(i + 1) + std::to_string(j + 1);
      const double delta = i == j ? 1.0 : 0.0;
      e.questions.push_back({id,
                             "$K_{" + std::to_string(i + 1) + std::to_string(j + 1) + "}$",
                             K(i, j),
                             1e-4,
                             false,
                             {{"reflectance of column j used (F diag(rho) instead of diag(rho) F)",
                               delta - d->rho[j] * d->F(i, j)},
                              {"F_ji used for F_ij (F transposed)", delta - d->rho[i] * d->F(j, i)},
                              {"sign of rho F (I + diag(rho) F)", delta + d->rho[i] * d->F(i, j)}}});
    }
    e.solution.push_back(row + ".");
  }
  e.solution.push_back("$K = " + matrixLatex(K, 5) + "$.");
  addDuctData(e, *d);
  e.figure = ductFigure(*d);
  addDuctScene(e, *d);
  return e;
}

}  // namespace rt::homework
