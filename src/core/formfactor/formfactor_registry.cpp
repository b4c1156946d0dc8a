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

}  // namespace rt
