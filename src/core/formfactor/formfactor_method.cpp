#include "core/formfactor/formfactor_method.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <stdexcept>

namespace rt {
namespace {

std::map<std::string, FormFactorMethodFactory>& registry() {
  static std::map<std::string, FormFactorMethodFactory> methods;
  return methods;
}
std::mutex& registryMutex() {
  static std::mutex m;
  return m;
}

}  // namespace

// Defined in formfactor_registry.cpp: registers the built-in methods once.
void registerBuiltinFormFactorMethods();

namespace {

// Rows of F above 1 beyond round-off: the element would pass on more light than leaves it. Methods that cast
// rays overshoot by their sampling noise (16 rays per pair: a few tenths of a percent in a closed room),
// which their accuracy knob controls; only an overshoot well beyond that is worth a warning. A method that
// states an error per entry (quadrature, exact) may overshoot by the sum of those over the row.
constexpr double kRowSumSlack = 1e-6, kRowSumSlackWithRays = 1e-2;
constexpr int kRowsNamed = 8;

void addWarnings(const FormFactorMethod& method, const FormFactorOptions& options, const FormFactorMatrix& F,
                 const RowSums& rows, FormFactorStats& stats) {
  if (stats.pairsOccludersIgnored > 0)
    stats.warnings.push_back(method.name() + " ignored occluders for " +
                             std::to_string(stats.pairsOccludersIgnored) +
                             " element pairs whose line of sight may be blocked, so their F is too large; "
                             "quadrature (the default) or exact account for occluders");
  const double slack = stats.raysCast > 0 ? kRowSumSlackWithRays : kRowSumSlack;
  std::vector<Eigen::Index> above;
  double largest = 0;
  for (Eigen::Index i = 0; i < F.rows(); ++i) {
    const double sum = rows.sums[i];
    // The allowance is at least the slack (the methods' errors are never negative): only a row above it
    // asks the method for its entries' errors.
    if (!(sum > 1 + slack)) continue;
    double allowance = slack;
    for (Eigen::Index j = 0; j < F.cols(); ++j)
      if (F(i, j) > 0) allowance += method.entryErrorBound(F(i, j), options);
    if (sum > 1 + allowance) {
      above.push_back(i);
      largest = std::max(largest, sum);
    }
  }
  if (above.empty()) return;
  std::string named;
  for (std::size_t k = 0; k < above.size() && k < kRowsNamed; ++k)
    named += (k == 0 ? "" : ", ") + std::to_string(above[k]);
  if (above.size() > kRowsNamed) named += " and " + std::to_string(above.size() - kRowsNamed) + " more";
  char line[200];
  std::snprintf(line, sizeof line,
                "%zu of %ld rows of F sum to more than 1 (up to %.6g) beyond the method's stated error: "
                "elements %s",
                above.size(), static_cast<long>(F.rows()), largest, named.c_str());
  stats.warnings.push_back(std::string(line) +
                           ": those elements would pass on more light than leaves them, and the solve "
                           "overestimates. " +
                           (stats.pairsOccludersIgnored > 0
                                ? "Occluders were ignored (see above)."
                                : "A finer method setting (or a finer mesh near shared edges) reduces it."));
}

// The options with the method's own default for an unset tolerance.
FormFactorOptions resolvedOptions(const FormFactorMethod& method, const FormFactorOptions& options) {
  const AccuracyKnob own = method.knob();
  FormFactorOptions resolved = options;
  if (resolved.tolerance <= 0 && own.field == AccuracyKnob::Field::Tolerance)
    resolved.tolerance = own.defaultValue;
  return resolved;
}

}  // namespace

FormFactorMatrix FormFactorMethod::compute(const Mesh& mesh, const FormFactorOptions& options,
                                           Progress& progress, FormFactorStats& stats) const {
  const FormFactorOptions resolved = resolvedOptions(*this, options);
  FormFactorMatrix F = computeMatrix(mesh, resolved, progress, stats);
  const RowSums rows = sumRows(F);
  checkRows(mesh, resolved, F, rows, stats);
  addWarnings(*this, resolved, F, rows, stats);
  return F;
}

FormFactorMatrix FormFactorMethod::fromRows(FormFactorMatrix F, const Mesh& mesh,
                                            const FormFactorOptions& options, FormFactorStats& stats) const {
  const auto n = static_cast<Eigen::Index>(mesh.size());
  if (!rowsAreIndependent())
    throw std::invalid_argument("form factors '" + name() + "' are not computed row by row on their own");
  if (F.rows() != n || F.cols() != n)
    throw std::invalid_argument("form factors '" + name() + "': the rows given are not the mesh's");
  const FormFactorOptions resolved = resolvedOptions(*this, options);
  stats.elements = mesh.size();
  const RowSums rows = sumRows(F);
  checkRows(mesh, resolved, F, rows, stats);
  addWarnings(*this, resolved, F, rows, stats);
  return F;
}

void FormFactorMethod::checkRows(const Mesh&, const FormFactorOptions&, const FormFactorMatrix&,
                                 const RowSums&, FormFactorStats&) const {}

double FormFactorMethod::entryErrorBound(double, const FormFactorOptions&) const {
  return 0;
}

FormFactorOptions FormFactorMethod::significantOptions(const FormFactorOptions& options) const {
  if (!readsOnlyItsKnob()) return options;
  const AccuracyKnob own = knob();
  return own.applied(FormFactorOptions{}, own.valueIn(options));
}

std::string FormFactorStats::summary() const {
  char line[512];
  std::snprintf(
      line, sizeof line,
      "%zu elements, %zu pairs computed, skipped: %zu facing away, %zu by reciprocity; %zu pairs needed no "
      "visibility, %zu rays, %.3f s",
      elements, pairsComputed, pairsSkippedFacing, pairsByReciprocity, pairsUnoccluded, raysCast, seconds);
  std::string s = line;
  if (kernelEvaluations > 0 || contourIntegrals > 0)
    s += ", " + std::to_string(kernelEvaluations) + " point evaluations, " +
         std::to_string(contourIntegrals) + " contour integrals";
  if (standardError > 0) s += ", standard error " + std::to_string(standardError);
  if (!notes.empty()) s += " (" + notes + ")";
  return s;
}

void registerFormFactorMethod(const std::string& name, FormFactorMethodFactory factory) {
  std::lock_guard lock(registryMutex());
  registry()[name] = std::move(factory);
}

std::unique_ptr<FormFactorMethod> makeFormFactorMethod(const std::string& name) {
  registerBuiltinFormFactorMethods();
  std::lock_guard lock(registryMutex());
  auto it = registry().find(name);
  if (it == registry().end()) {
    const auto& optional = optionalFormFactorMethods();
    if (std::find(optional.begin(), optional.end(), name) != optional.end())
      throw std::invalid_argument(
          "the form-factor method '" + name +
          "' is not in this build: it needs the exact layer (CGAL; RT_BUILD_EXACT=ON)");
    std::string known;
    for (const auto& [key, factory] : registry()) known += (known.empty() ? "" : ", ") + key;
    throw std::invalid_argument("unknown form-factor method '" + name + "' (known: " + known + ")");
  }
  return it->second();
}

std::vector<std::string> formFactorMethodNames() {
  registerBuiltinFormFactorMethods();
  std::lock_guard lock(registryMutex());
  std::vector<std::string> names;
  for (const auto& [key, factory] : registry()) names.push_back(key);
  return names;
}

}  // namespace rt

namespace rt {

FormFactorOptions AccuracyKnob::applied(FormFactorOptions options, double value) const {
  switch (field) {
    case Field::Resolution:
      options.hemicubeResolution = static_cast<int>(value);
      break;
    case Field::Samples:
      options.samples = static_cast<int>(value);
      break;
    case Field::Tolerance:
      options.tolerance = value;
      break;
    case Field::None:
      break;
  }
  return options;
}

double AccuracyKnob::fromSweep(int v) const {
  return field == Field::Tolerance ? std::pow(10.0, -v) : static_cast<double>(v);
}

double AccuracyKnob::valueIn(const FormFactorOptions& options) const {
  switch (field) {
    case Field::Resolution:
      return options.hemicubeResolution;
    case Field::Samples:
      return options.samples;
    case Field::Tolerance:
      return options.tolerance;
    case Field::None:
      break;
  }
  return 0;
}

AccuracyKnob accuracyKnobOf(const std::string& method) {
  try {
    return makeFormFactorMethod(method)->knob();
  } catch (const std::invalid_argument&) {
    return {};
  }
}

}  // namespace rt
