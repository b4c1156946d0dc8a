// How fast light settles: the k-th term of the Neumann series B = sum_k (diag(rho) F)^k E and its share of
// the power, and the spectral radius of diag(rho) F that sets how many sweeps an iteration needs.
#include <Eigen/Eigenvalues>
#include <cmath>

#include "homework/duct.h"
#include "homework/topics.h"

namespace rt::homework {

std::optional<Exercise> generateBounces(Draw& draw) {
  const int n = draw.integer(3, 4);
  std::optional<Duct> d = drawDuct(draw, n, 0.3, 0.9);
  if (!d) return std::nullopt;
  const int k = draw.integer(1, 3);
  const Eigen::MatrixXd M = d->rho.asDiagonal() * d->F;
  std::vector<Eigen::VectorXd> terms{d->E};
  for (int m = 1; m <= k + 1; ++m) terms.push_back(M * terms.back());
  const Eigen::VectorXd B = ductK(*d).partialPivLu().solve(d->E);
  std::vector<double> power;
  for (const auto& t : terms) power.push_back(t.dot(d->length));
  const double total = B.dot(d->length), share = power[k] / total;
  Exercise e;
  e.title = "The k-th bounce";
  const std::string ks = std::to_string(k);
  e.statement =
      ductStatement(*d) +
      " Light leaves the emitters (bounce 0) and is reflected again and again: "
      "$B = \\sum_{m \\ge 0} (\\operatorname{diag}(\\rho)F)^m E$. Give the radiosity after exactly one "
      "reflection (term $m = 1$), the power per unit length carried by bounce $k = " +
      ks + "$, $P_" + ks + " = \\sum_i L_i\\,[(\\operatorname{diag}(\\rho)F)^{" + ks +
      "}E]_i$, and its share of the total power $\\sum_i L_i B_i$ of the solution.";
  e.hint =
      "Multiply by $\\operatorname{diag}(\\rho)F$ once per bounce; the total is $\\sum_i L_iB_i$ with $B$ "
      "from "
      "$KB = E$ (or the sum of all terms).";
  for (std::size_t m = 0; m < terms.size() && m <= static_cast<std::size_t>(k); ++m)
    e.solution.push_back("Term $m = " + std::to_string(m) + "$: $" + vectorLatex(terms[m], 6) + "$, power $" +
                         num(power[m], 6) + "$.");
  e.solution.push_back("Solution $B = " + vectorLatex(B, 6) +
                       "$, total power $\\sum_i L_iB_i = " + num(total, 6) + "$.");
  e.solution.push_back("Share of bounce " + ks + ": $" + num(power[k], 6) + " / " + num(total, 6) + " = " +
                       num(share, 6) + "$.");
  const double scale = d->E.maxCoeff();
  for (int i = 0; i < n; ++i)
    e.questions.push_back({"T1[" + std::to_string(i + 1) + "]",
                           "after one reflection, term 1, entry " + std::to_string(i + 1),
                           terms[1][i],
                           tolerance(terms[1][i], 0.002, 2e-4 * scale),
                           false,
                           {{"F_ji used for F_ij (F transposed)", d->rho[i] * d->F.col(i).dot(d->E)}}});
  e.questions.push_back({"P",
                         "power of bounce " + ks,
                         power[k],
                         tolerance(power[k], 0.003, 1e-4 * scale),
                         false,
                         {{"one bounce too few", power[k - 1]}, {"one bounce too many", power[k + 1]}}});
  e.questions.push_back({"share",
                         "share of bounce " + ks + " in the total power",
                         share,
                         tolerance(share, 0.003, 1e-4),
                         false,
                         {{"share of the emitted power, not of the total", power[k] / power[0]},
                          {"radiosities summed without the side lengths", terms[k].sum() / B.sum()}}});
  if (!(share > 1e-3)) return std::nullopt;
  addDuctData(e, *d);
  e.figure = ductFigure(*d);
  addDuctScene(e, *d);
  return e;
}

std::optional<Exercise> generateSpectralRadius(Draw& draw) {
  const int n = draw.integer(3, 4);
  std::optional<Duct> d = drawDuct(draw, n, 0.2, 0.95);
  if (!d) return std::nullopt;
  const Eigen::MatrixXd M = d->rho.asDiagonal() * d->F;
  const Eigen::VectorXd rowSums = M.rowwise().sum();
  const double r = M.eigenvalues().cwiseAbs().maxCoeff();
  const int exponent = draw.integer(3, 6);
  const double tol = std::pow(10.0, -exponent);
  const double ratio = std::log(tol) / std::log(r);
  // Well-posed: a spread of reflectances (else r is just rho) and a count that rounding of r cannot change.
  if (!(r < 0.95) || rowSums.maxCoeff() - rowSums.minCoeff() < 0.1 ||
      std::abs(ratio - std::round(ratio)) < 0.05)
    return std::nullopt;
  const int m = static_cast<int>(std::ceil(ratio));
  Exercise e;
  e.title = "Spectral radius and iteration count";
  e.given = {{"exponent", exponent}};
  e.statement =
      ductStatement(*d) +
      " The error of Jacobi's iteration shrinks like $r^m$, with $r$ the spectral "
      "radius of $M = \\operatorname{diag}(\\rho)F$. Give the smallest and the largest row sum of $M$ "
      "(bounds on $r$), $r$ itself, and the number of sweeps $m$ after which $r^m \\le 10^{-" +
      std::to_string(exponent) + "}$.";
  e.hint =
      "$M$ is non-negative: $r$ lies between its smallest and largest row sums (Perron-Frobenius); power "
      "iteration $x \\leftarrow Mx/\\|Mx\\|$ converges to it. Then $m = \\lceil \\ln\\tau / \\ln r\\rceil$.";
  e.solution.push_back("$M = " + matrixLatex(M, 5) + "$; row sums $" + vectorLatex(rowSums, 6) + "$.");
  Eigen::VectorXd x = Eigen::VectorXd::Ones(n);
  for (int it = 1; it <= 3; ++it) {
    const Eigen::VectorXd y = M * x;
    e.solution.push_back("Power iteration " + std::to_string(it) + ": $Mx = " + vectorLatex(y, 6) +
                         "$, ratio $\\max_i (Mx)_i/x_i = " + num((y.array() / x.array()).maxCoeff(), 6) +
                         "$.");
    x = y / y.maxCoeff();
  }
  e.solution.push_back("Converged: $r = " + num(r, 6) + "$ (the largest eigenvalue modulus of $M$).");
  e.solution.push_back("$\\ln 10^{-" + std::to_string(exponent) + "} / \\ln " + num(r, 6) + " = " +
                       num(ratio, 6) + "$, so $m = " + std::to_string(m) + "$.");
  e.questions = {
      {"rowmin", "smallest row sum of $M$", rowSums.minCoeff(), 2e-4, false, {}},
      {"rowmax",
       "largest row sum of $M$",
       rowSums.maxCoeff(),
       2e-4,
       false,
       {{"largest reflectance given (rows of F taken to sum to 1)", d->rho.maxCoeff()}}},
      {"r",
       "spectral radius $r$",
       r,
       tolerance(r, 0.002, 2e-4),
       false,
       {{"largest row sum given for r (only an upper bound)", rowSums.maxCoeff()},
        {"largest reflectance given for r", d->rho.maxCoeff()}}},
      {"m",
       "sweeps $m$",
       static_cast<double>(m),
       0.5,
       true,
       {{"rounded down instead of up", static_cast<double>(m - 1)},
        {"largest row sum used for r", std::ceil(std::log(tol) / std::log(rowSums.maxCoeff()))}}},
  };
  addDuctData(e, *d);
  e.figure = ductFigure(*d);
  addDuctScene(e, *d);
  return e;
}

}  // namespace rt::homework
