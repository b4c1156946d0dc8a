#include "plugins/optional_methods.h"

#ifdef RT_HAVE_EXACT
#include "exact/discontinuity_triangulation.h"
#include "exact/exact_reference.h"
#endif

namespace rt {

void registerOptionalMethods() {
  static const bool once = [] {
#ifdef RT_HAVE_EXACT
    rt::exact::registerExactMethod();
    rt::exact::registerDiscontinuityTriangulation();
#endif
    return true;
  }();
  (void)once;
}

}  // namespace rt
