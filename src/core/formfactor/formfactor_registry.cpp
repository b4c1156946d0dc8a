#include <algorithm>

#include "core/formfactor/analytic_method.h"
#include "core/formfactor/formfactor_method.h"

namespace rt {

const std::string& defaultFormFactorMethod() {
  static const std::string name = "quadrature";
  return name;
}

void registerBuiltinFormFactorMethods() {
  static const bool once = [] {
    registerFormFactorMethod("analytic", [] { return makeAnalyticMethod(false); });
    registerFormFactorMethod("analytic-visibility", [] { return makeAnalyticMethod(true); });
    registerFormFactorMethod("raycast", [] { return makeRaycastMethod(); });
    registerFormFactorMethod("montecarlo", [] { return makeMonteCarloMethod(); });
    registerFormFactorMethod("hemicube", [] { return makeHemicubeMethod(); });
    registerFormFactorMethod("nusselt", [] { return makeNusseltMethod(); });
    registerFormFactorMethod("hybrid", [] { return makeHybridMethod(); });
    registerFormFactorMethod("quadrature", [] { return makeQuadratureMethod(); });
    return true;
  }();
  (void)once;
}

const std::vector<std::string>& optionalFormFactorMethods() {
  static const std::vector<std::string> names{"exact"};
  return names;
}

std::vector<std::string> declaredFormFactorMethods() {
  std::vector<std::string> names = formFactorMethodNames();
  for (const std::string& name : optionalFormFactorMethods())
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace rt
