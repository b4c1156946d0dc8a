#include "app/registration.h"

#ifdef RT_HAVE_EXACT
#include "exact/exact_reference.h"
#endif

namespace rt::app {

void registerOptionalMethods() {
#ifdef RT_HAVE_EXACT
  static const bool once = [] {
    rt::exact::registerExactMethod();
    return true;
  }();
  (void)once;
#endif
}

}  // namespace rt::app
