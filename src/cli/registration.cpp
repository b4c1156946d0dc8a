#include "cli/registration.h"

#ifdef RT_HAVE_EXACT
#include "exact/exact_reference.h"
#endif

namespace rt::cli {

void registerOptionalMethods() {
#ifdef RT_HAVE_EXACT
  rt::exact::registerExactMethod();
#endif
}

}  // namespace rt::cli
