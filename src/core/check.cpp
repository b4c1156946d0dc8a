#include "core/check.h"

namespace rt {

bool checksEnabled() {
#if defined(RT_ENABLE_CHECKS) && RT_ENABLE_CHECKS
  return true;
#else
  return false;
#endif
}

void checkFailed(const char* file, int line, const char* condition, const std::string& message) {
  throw CheckFailure(std::string(file) + ":" + std::to_string(line) +
                     ": internal check failed: " + condition + ": " + message);
}

}  // namespace rt
