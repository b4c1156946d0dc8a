#include "core/formfactor/formfactor_method.h"

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

std::string FormFactorStats::summary() const {
  char line[512];
  std::snprintf(
      line, sizeof line,
      "%zu elements, %zu pairs computed, skipped: %zu facing away, %zu by reciprocity; %zu pairs needed no "
      "visibility, %zu rays, %.3f s",
      elements, pairsComputed, pairsSkippedFacing, pairsByReciprocity, pairsUnoccluded, raysCast, seconds);
  std::string s = line;
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
