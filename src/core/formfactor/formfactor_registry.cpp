#include "core/formfactor/formfactor_method.h"

namespace rt {

void registerBuiltinFormFactorMethods() {
  static const bool once = [] {
    // Built-in methods are added here as they land.
    return true;
  }();
  (void)once;
}

}  // namespace rt
