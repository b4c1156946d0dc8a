#include "app/wording.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <algorithm>

#include "lesson/step_keys.h"

namespace rt::app {

QString counted(long long n, const QString& singular, const QString& plural) {
  const QString word = n == 1 ? singular : (plural.isEmpty() ? singular + "s" : plural);
  return QString("%1 %2").arg(n).arg(word);
}

bool isStochasticSolver(const std::string& solver) {
  // The solver table's own word for it: the solvers whose budget is a number of rays (or walks).
  for (const SolverInfo& info : solverTable())
    if (info.name == solver)
      return std::find(info.settings.begin(), info.settings.end(), "rays-per-iteration") !=
             info.settings.end();
  return false;
}

QString iterationUnit(const std::string& solver) {
  return solver == "bounces" ? QStringLiteral("bounce") : QStringLiteral("iteration");
}

QString statusText(const std::string& solver, SolverStatus status) {
  // A stochastic solver runs until its ray budget is spent: that is the end it was built for, and what
  // remains is noise, not a failure to converge.
  if (status == SolverStatus::NoConvergence && isStochasticSolver(solver))
    return QCoreApplication::translate("rt::app", "noise level reached");
  return QString::fromStdString(toString(status));
}

QString solveSummary(const std::string& solver, SolverStatus status, int iterations, double residual) {
  return QString("%1: %2 after %3, residual %4")
      .arg(QString::fromStdString(solver), statusText(solver, status),
           counted(iterations, iterationUnit(solver)))
      .arg(residual, 0, 'g', 3);
}

QString solveSummary(const PipelineResult& r) {
  const std::vector<int> numbers = iterationNumbers(r);
  const int count = r.solverName == "bounces" && !numbers.empty() ? numbers.back() : r.iterations;
  return solveSummary(r.solverName, r.status, count, r.residual);
}

std::vector<int> iterationNumbers(const PipelineResult& r) {
  std::vector<int> numbers;
  numbers.reserve(r.history.size());
  for (std::size_t k = 0; k < r.history.size(); ++k)
    numbers.push_back(r.solverName == "bounces" ? static_cast<int>(k) : r.history[k].iteration);
  return numbers;
}

QString inAppTerms(const QString& message) {
  static const QRegularExpression option(QStringLiteral("--([a-z][a-z0-9-]*)"));
  QString out;
  qsizetype from = 0;
  for (auto it = option.globalMatch(message); it.hasNext();) {
    const QRegularExpressionMatch m = it.next();
    const std::string name = m.captured(1).toStdString();
    const lesson::StepKey* key = lesson::findStepKey(name == "no-subdivide" ? "subdivide" : name);
    out += message.mid(from, m.capturedStart() - from);
    from = m.capturedEnd();
    if (!key || !key->control || key->label.empty()) {
      out += m.captured();
      continue;
    }
    out += QCoreApplication::translate("rt::app", "the %1 control").arg(QString::fromStdString(key->label));
    if (name == "no-subdivide")
      out += " at 1";
    else if (from + 1 < message.size() && message[from] == ' ' && message[from + 1].isLetterOrNumber())
      out += " at";  // "--max-edge 40": "the Max edge control at 40"
  }
  return out + message.mid(from);
}

}  // namespace rt::app
