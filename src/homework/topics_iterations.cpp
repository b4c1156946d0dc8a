// Iterations by hand on a duct (duct.h): Jacobi and Gauss-Seidel sweeps from B = E, and Southwell shooting
// from the unshot radiosity E. Written from the textbook's update rules; the tests run the core's solvers on
// the same numbers.
#include <algorithm>
#include <cmath>

#include "homework/duct.h"
#include "homework/topics.h"

namespace rt::homework {
namespace {

std::string idx(int i) {
  return std::to_string(i + 1);
}

// Sweeps of B_i <- E_i + rho_i sum_j F_ij B_j; Gauss-Seidel reads the values of this sweep as soon as they
// exist.
Eigen::VectorXd sweep(const Duct& d, const Eigen::VectorXd& B, bool gaussSeidel) {
  Eigen::VectorXd next = B;
  for (Eigen::Index i = 0; i < B.size(); ++i)
    next[i] = d.E[i] + d.rho[i] * d.F.row(i).dot(gaussSeidel ? next : B);
  return next;
}

}  // namespace

std::optional<Exercise> generateJacobiGaussSeidel(Draw& draw) {
  const int n = draw.integer(3, 4);
  std::optional<Duct> d = drawDuct(draw, n, 0.3, 0.8);
  if (!d) return std::nullopt;
  const Eigen::MatrixXd K = ductK(*d);
  const Eigen::VectorXd exact = K.partialPivLu().solve(d->E);
  const Eigen::VectorXd J1 = sweep(*d, d->E, false), J2 = sweep(*d, J1, false);
  const Eigen::VectorXd G1 = sweep(*d, d->E, true), G2 = sweep(*d, G1, true);
  Exercise e;
  e.title = "Jacobi and Gauss-Seidel by hand";
  e.statement =
      ductStatement(*d) +
      " Starting from $B^{(0)} = E$, do two Jacobi sweeps and, again from $E$, two Gauss-Seidel sweeps "
      "(elements in the order 1, 2, ...). Then solve $KB = E$ exactly.";
  e.hint =
      "Jacobi: $B_i^{(k+1)} = E_i + \\rho_i\\sum_j F_{ij}B_j^{(k)}$ with only old values; Gauss-Seidel uses "
      "each new $B_j$ as soon as it is computed in the same sweep.";
  auto& s = e.solution;
  s.push_back("Jacobi sweep 1: $B^{(1)} = " + vectorLatex(J1, 6) +
              "$; sweep 2: $B^{(2)} = " + vectorLatex(J2, 6) + "$.");
  Eigen::VectorXd g = d->E;
  for (int k = 1; k <= 2; ++k)
    for (int i = 0; i < n; ++i) {
      const double gathered = d->F.row(i).dot(g);
      g[i] = d->E[i] + d->rho[i] * gathered;
      s.push_back("Gauss-Seidel sweep " + std::to_string(k) + ", element " + idx(i) + ": $\\sum_j F_{" +
                  idx(i) + "j}B_j = " + num(gathered, 6) + "$, $B_" + idx(i) + " = " + num(d->E[i]) + " + " +
                  num(d->rho[i]) + " \\times " + num(gathered, 6) + " = " + num(g[i], 6) + "$.");
    }
  s.push_back("Exact: $B = K^{-1}E = " + vectorLatex(exact, 6) + "$.");
  const double scale = d->E.maxCoeff();
  auto add = [&](const std::string& name, const std::string& what, const Eigen::VectorXd& v,
                 const Eigen::VectorXd* asJacobi, const Eigen::VectorXd* other,
                 const std::string& otherName) {
    for (int i = 0; i < n; ++i) {
      Question q{name + "[" + idx(i) + "]",
                 what + ", $B_" + idx(i) + "$",
                 v[i],
                 tolerance(v[i], 0.002, 2e-4 * scale),
                 false,
                 {}};
      if (asJacobi)
        q.mistakes.push_back({"Gauss-Seidel step done as Jacobi (old values used)", (*asJacobi)[i]});
      if (other) q.mistakes.push_back({otherName, (*other)[i]});
      e.questions.push_back(q);
    }
  };
  add("J1", "Jacobi sweep 1", J1, nullptr, nullptr, "");
  add("J2", "Jacobi sweep 2", J2, nullptr, &G2, "Gauss-Seidel values given for Jacobi");
  add("G1", "Gauss-Seidel sweep 1", G1, &J1, nullptr, "");
  add("G2", "Gauss-Seidel sweep 2", G2, &J2, nullptr, "");
  add("B", "exact solution", exact, nullptr, &J2, "two Jacobi sweeps given for the exact solution");
  addDuctData(e, *d);
  e.figure = ductFigure(*d);
  addDuctScene(e, *d);
  return e;
}

std::optional<Exercise> generateSouthwell(Draw& draw) {
  const int n = draw.integer(3, 4);
  std::optional<Duct> d = drawDuct(draw, n, 0.4, 0.9);
  if (!d) return std::nullopt;
  Exercise e;
  e.title = "Southwell shooting";
  e.statement =
      ductStatement(*d) +
      " Starting from $B = \\Delta B = E$ (the unshot radiosity), do three Southwell shots: each time "
      "shoot from the side with the most unshot power $\\Delta B_i L_i$. After each shot give the "
      "shooter, $B$ and the total unshot power $\\sum_i \\Delta B_i L_i$.";
  e.hint =
      "A shot from $i$ adds $\\Delta B_j \\mathrel{+}= \\rho_j F_{ji}\\Delta B_i$ to every $j$ (the same as "
      "$\\rho_j F_{ij}\\Delta B_i L_i / L_j$ by reciprocity), then sets $\\Delta B_i = 0$.";
  Eigen::VectorXd B = d->E, dB = d->E;
  const double scale = d->E.maxCoeff();
  for (int shot = 1; shot <= 3; ++shot) {
    const Eigen::VectorXd power = dB.cwiseProduct(d->length);
    Eigen::Index i = 0;
    power.maxCoeff(&i);
    // Well-posed: the shooter must be clear, not a near tie that rounding could flip.
    Eigen::VectorXd others = power;
    others[i] = -1;
    if (power[i] <= 0 || others.maxCoeff() > 0.97 * power[i]) return std::nullopt;
    const double shotB = dB[i];
    Eigen::VectorXd wrongB = B;  // the slip of using F_ij without the area ratio
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const double add = d->rho[j] * d->F(j, i) * shotB;
      B[j] += add;
      dB[j] += add;
      wrongB[j] += d->rho[j] * d->F(i, j) * shotB;
    }
    dB[i] = 0;
    const double unshot = dB.dot(d->length);
    const std::string k = std::to_string(shot);
    e.solution.push_back("Shot " + k + ": unshot powers $\\Delta B_i L_i = " + vectorLatex(power, 6) +
                         "$, shooter " + idx(static_cast<int>(i)) + " with $\\Delta B = " + num(shotB, 6) +
                         "$; $B = " + vectorLatex(B, 6) + "$, $\\Delta B = " + vectorLatex(dB, 6) +
                         "$, unshot power $" + num(unshot, 6) + "$.");
    e.questions.push_back(
        {"shooter" + k, "shot " + k + ": the shooter", static_cast<double>(i + 1), 0.5, true, {}});
    for (int j = 0; j < n; ++j)
      e.questions.push_back({"B" + k + "[" + idx(j) + "]",
                             "after shot " + k + ", $B_" + idx(j) + "$",
                             B[j],
                             tolerance(B[j], 0.002, 2e-4 * scale),
                             false,
                             {{"F_ij used where the shot needs F_ji (areas ignored)", wrongB[j]}}});
    e.questions.push_back({"unshot" + k,
                           "after shot " + k + ", the unshot power",
                           unshot,
                           tolerance(unshot, 0.002, 2e-4 * scale),
                           false,
                           {{"unshot radiosity summed without the side lengths", dB.sum()}}});
  }
  addDuctData(e, *d);
  e.figure = ductFigure(*d);
  addDuctScene(e, *d);
  return e;
}

}  // namespace rt::homework
