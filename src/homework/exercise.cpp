#include "homework/exercise.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rt::homework {

const Question* Exercise::find(const std::string& id) const {
  for (const Question& q : questions)
    if (q.id == id) return &q;
  return nullptr;
}

std::string num(double value, int digits) {
  if (value == 0 || !std::isfinite(value)) return value == 0 ? "0" : std::to_string(value);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  std::string s = buffer;
  // %g switches to exponents for small numbers; LaTeX and students read 1.2e-05 badly.
  const auto e = s.find('e');
  if (e != std::string::npos) {
    const std::string mantissa = s.substr(0, e);
    const int exponent = std::stoi(s.substr(e + 1));
    return mantissa + " \\times 10^{" + std::to_string(exponent) + "}";
  }
  return s;
}

std::string vectorLatex(const Eigen::VectorXd& v, int digits) {
  std::string out = "(";
  for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ",\\ " : "") + num(v[i], digits);
  return out + ")";
}

std::string matrixLatex(const Eigen::MatrixXd& m, int digits) {
  std::string out = "\\begin{bmatrix}";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    for (Eigen::Index j = 0; j < m.cols(); ++j) out += (j ? " & " : " ") + num(m(i, j), digits);
    out += i + 1 < m.rows() ? " \\\\" : " ";
  }
  return out + "\\end{bmatrix}";
}

std::string markdownTable(const Eigen::MatrixXd& m, const std::vector<std::string>& columns, int digits) {
  std::string out = "| $k$ |", rule = "|---|";
  for (const std::string& c : columns) out += " " + c + " |", rule += "---|";
  out += "\n" + rule + "\n";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    out += "| " + std::to_string(i + 1) + " |";
    for (Eigen::Index j = 0; j < m.cols(); ++j) out += " " + num(m(i, j), digits) + " |";
    out += "\n";
  }
  return out;
}

double tolerance(double answer, double relative, double absolute) {
  return std::max(std::abs(answer) * relative, absolute);
}

void pruneMistakes(Question& q) {
  std::vector<Mistake> kept;
  for (const Mistake& m : q.mistakes) {
    // Outside twice the tolerance, a submission cannot be within tolerance of both (integers: a whole step).
    const double apart = q.integer ? 1 - 1e-9 : 2 * q.tolerance;
    if (!std::isfinite(m.value) || std::abs(m.value - q.answer) < apart) continue;
    // Two slips that give the same number cannot be told apart: keep the first named.
    const bool duplicate = std::any_of(kept.begin(), kept.end(), [&](const Mistake& k) {
      return std::abs(k.value - m.value) <= q.tolerance;
    });
    if (!duplicate) kept.push_back(m);
  }
  q.mistakes = std::move(kept);
}

}  // namespace rt::homework
