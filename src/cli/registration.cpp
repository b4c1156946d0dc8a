#include "cli/registration.h"

#ifdef RT_HAVE_EXACT
#include "exact/discontinuity_triangulation.h"
#include "exact/exact_reference.h"
#endif

namespace rt::cli {

void registerOptionalMethods() {
#ifdef RT_HAVE_EXACT
  rt::exact::registerExactMethod();
  rt::exact::registerDiscontinuityTriangulation();
#endif
}

}  // namespace rt::cli
