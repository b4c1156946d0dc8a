// One iteration of regular stochastic Jacobi by hand on a duct (duct.h), from a printed table of random
// numbers: each line's source side drawn in proportion to the power it shoots, its landing side from the
// source's row of F (both by the running sums the table's numbers fall into), every line carrying P_T / N.
// Written from the textbook's estimator (Dutré, Bekaert and Bala 2006, sec. 6.3), not from the core's solver.
#include <cmath>

#include "homework/duct.h"
#include "homework/topics.h"

namespace rt::homework {
namespace {

std::string idx(int i) {
  return std::to_string(i + 1);
}

// The index k with running[k-1] <= u < running[k]; -1 when u is at or past the last running sum.
int pick(const Eigen::VectorXd& weights, double u) {
  double running = 0;
  for (Eigen::Index k = 0; k < weights.size(); ++k) {
    running += weights[k];
    if (u < running) return static_cast<int>(k);
  }
  return -1;
}

}  // namespace

std::optional<Exercise> generateStochasticJacobi(Draw& draw) {
  const int n = draw.integer(3, 4);
  std::optional<Duct> d = drawDuct(draw, n, 0.3, 0.8);
  if (!d) return std::nullopt;
  const int N = draw.integer(8, 10);
  const Eigen::VectorXd power = d->E.cwiseProduct(d->length);  // P_i = E_i L_i: B^(0) = E shoots its emission
  const double total = power.sum();
  if (!(total > 0)) return std::nullopt;
  const double perRay = total / N;
  Eigen::MatrixXd table(N, 2);
  Eigen::VectorXd counts = Eigen::VectorXd::Zero(n);
  std::vector<std::pair<int, int>> paths;
  for (int k = 0; k < N; ++k) {
    table(k, 0) = std::round(1000 * draw.uniform()) / 1000;
    table(k, 1) = std::round(1000 * draw.uniform()) / 1000;
    const int from = pick(power / total, table(k, 0));
    if (from < 0) return std::nullopt;
    const int to = pick(d->F.row(from).transpose(), table(k, 1));
    if (to < 0) return std::nullopt;  // past the rounded row's sum: the table would need a rule for it
    // A number within 0.002 of a running sum's boundary is too close to call by hand.
    double running = 0;
    for (int m = 0; m < n; ++m) {
      running += power[m] / total;
      if (std::abs(table(k, 0) - running) < 0.002) return std::nullopt;
    }
    running = 0;
    for (int m = 0; m < n; ++m) {
      running += d->F(from, m);
      if (std::abs(table(k, 1) - running) < 0.002) return std::nullopt;
    }
    counts[to] += 1;
    paths.emplace_back(from, to);
  }
  // The element asked about: the one with the most hits that reflects, so that its estimate has noise.
  int asked = -1;
  for (int j = 0; j < n; ++j)
    if (counts[j] > 0 && d->rho[j] > 0 && (asked < 0 || counts[j] > counts[asked])) asked = j;
  if (asked < 0 || counts[asked] >= N) return std::nullopt;
  Eigen::VectorXd B1(n), noRho(n), noLength(n), exact(n);
  for (int j = 0; j < n; ++j) {
    const double received = counts[j] * perRay;
    B1[j] = d->E[j] + d->rho[j] * received / d->length[j];
    noRho[j] = d->E[j] + received / d->length[j];
    noLength[j] = d->E[j] + d->rho[j] * received;
    // The deterministic sweep the lines estimate: what lands on j, sum_i P_i F_ij, without noise.
    exact[j] = d->E[j] + d->rho[j] * power.dot(d->F.col(j)) / d->length[j];
  }
  const double p = counts[asked] / N;
  const double se = d->rho[asked] * total / d->length[asked] * std::sqrt(p * (1 - p) / N);

  Exercise e;
  e.title = "One iteration of stochastic Jacobi";
  e.given = {{"N", N}, {"total", total}, {"asked", asked + 1}};
  e.statement =
      ductStatement(*d) +
      " Do one iteration of regular stochastic Jacobi from $B^{(0)} = E$ with the $N = " + std::to_string(N) +
      "$ lines of the table `lines`: line $k$ leaves side $i$ where $u_k$ falls in the running sums of $P_i "
      "/ "
      "P_T$ ($P_i = E_i L_i$, $P_T = \\sum_i P_i$) and lands on side $j$ where $v_k$ falls in the running "
      "sums of row $i$ of $F$; every line carries $P_T / N$. Give (a) the power of one line, (b) how many "
      "lines land on each side, (c) $B^{(1)}_j = E_j + \\rho_j \\,(\\text{power received by } j) / L_j$ for "
      "every side, (d) the binomial standard error of $B^{(1)}_{" +
      idx(asked) + "}$, $\\rho_" + idx(asked) + " \\frac{P_T}{L_" + idx(asked) +
      "}\\sqrt{\\hat p(1 - \\hat p)/N}$ with $\\hat p$ the fraction of the lines that landed on side " +
      idx(asked) + ", and (e) the value the deterministic Jacobi sweep gives for $B^{(1)}_{" + idx(asked) +
      "}$.";
  e.statement += "\n\n" + markdownTable(table, {"$u_k$", "$v_k$"}) + "\n";
  e.hint =
      "Running sums: $u$ picks the first $i$ with $u < \\sum_{m \\le i} P_m / P_T$. The expected power "
      "landing on $j$ is $\\sum_i P_i F_{ij}$, so the deterministic sweep is $B_j = E_j + \\rho_j \\sum_i "
      "P_i F_{ij} / L_j$.";
  std::string walk;
  for (int k = 0; k < N; ++k)
    walk += (k ? ", " : "") + std::string("$") + idx(paths[k].first) + " \\to " + idx(paths[k].second) + "$";
  e.solution.push_back("$P = " + vectorLatex(power, 6) + "$, $P_T = " + num(total, 6) +
                       "$, each line carries $P_T / N = " + num(perRay, 6) + "$.");
  e.solution.push_back("The lines go " + walk + ": counts per side $" + vectorLatex(counts, 3) + "$.");
  e.solution.push_back("$B^{(1)} = " + vectorLatex(B1, 6) + "$ (sides that receive no line keep $E$).");
  e.solution.push_back("Side " + idx(asked) + ": $\\hat p = " + num(p, 4) + "$, standard error $" +
                       num(d->rho[asked], 4) + " \\times \\frac{" + num(total, 6) + "}{" +
                       num(d->length[asked], 4) + "}\\sqrt{" + num(p * (1 - p), 4) + " / " +
                       std::to_string(N) + "} = " + num(se, 6) + "$.");
  e.solution.push_back("The deterministic sweep gives $B^{(1)}_{" + idx(asked) +
                       "} = " + num(exact[asked], 6) + "$: the estimate is " +
                       num(std::abs(B1[asked] - exact[asked]) / se, 3) + " standard errors from it.");
  const double scale = d->E.maxCoeff();
  e.questions.push_back({"perRay",
                         "(a) the power of one line",
                         perRay,
                         tolerance(perRay, 0.002, 1e-6),
                         false,
                         {{"emission summed without the side lengths", d->E.sum() / N}}});
  for (int j = 0; j < n; ++j)
    e.questions.push_back(
        {"count[" + idx(j) + "]", "(b) lines landing on side " + idx(j), counts[j], 0.5, true, {}});
  for (int j = 0; j < n; ++j)
    e.questions.push_back(
        {"B1[" + idx(j) + "]",
         "(c) $B^{(1)}_" + idx(j) + "$",
         B1[j],
         tolerance(B1[j], 0.002, 2e-4 * scale),
         false,
         {{"reflectance left out", noRho[j]}, {"not divided by the side length", noLength[j]}}});
  e.questions.push_back(
      {"SE",
       "(d) the standard error of $B^{(1)}_{" + idx(asked) + "}$",
       se,
       tolerance(se, 0.005, 1e-6),
       false,
       {{"not divided by sqrt N", se * std::sqrt(double(N))}, {"reflectance left out", se / d->rho[asked]}}});
  e.questions.push_back({"exact",
                         "(e) the deterministic sweep's $B^{(1)}_{" + idx(asked) + "}$",
                         exact[asked],
                         tolerance(exact[asked], 0.002, 2e-4 * scale),
                         false,
                         {{"the stochastic estimate given for the deterministic sweep", B1[asked]}}});
  e.data.push_back({"lines", table});
  addDuctData(e, *d);
  e.figure = ductFigure(*d);
  addDuctScene(e, *d);
  return e;
}

}  // namespace rt::homework
