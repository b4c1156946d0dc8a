#include "lesson/step_numbers.h"

#include <cmath>
#include <cstdio>
#include <map>

namespace rt::lesson {
namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return v > 0 ? "\"inf\"" : v < 0 ? "\"-inf\"" : "\"nan\"";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// Run times, and numbers derived from them (a time's slope against n, an extrapolated time in minutes or
// hours, a rate per second).
bool isTiming(const std::string& name) {
  return name.find("seconds") != std::string::npos || name.find("minutes") != std::string::npos ||
         name.rfind("hours.", 0) == 0 || name.find("per-second") != std::string::npos ||
         name.rfind("time-slope", 0) == 0;
}

}  // namespace

std::string stepNumbersJson(const StepResult& r) {
  std::map<std::string, std::string> fields;
  fields["elements"] = number(static_cast<double>(r.mesh.size()));
  if (r.B.rows() > 0)
    for (int c = 0; c < 3; ++c) fields[std::string("B.sum.") + "rgb"[c]] = number(r.B.col(c).sum());
  if (r.F) {
    const Eigen::VectorXd rows = r.F->rowwise().sum();
    fields["F.rowsum.min"] = number(rows.minCoeff());
    fields["F.rowsum.max"] = number(rows.maxCoeff());
    fields["F.sum"] = number(r.F->sum());
  }
  for (std::size_t k = 0; k < r.runs.size(); ++k) {
    const std::string prefix = "run[" + std::to_string(k) + "]." + r.runs[k].label;
    fields[prefix + ".iterations"] = number(r.runs[k].iterations);
    fields[prefix + ".residual"] = number(r.runs[k].residual);
  }
  for (const auto& [name, value] : r.values)
    if (!isTiming(name)) fields["value." + name] = number(value);
  std::string out = "{";
  for (const auto& [key, value] : fields) out += (out.size() > 1 ? ", " : "") + quoted(key) + ": " + value;
  return out + "}";
}

}  // namespace rt::lesson
