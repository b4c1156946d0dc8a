// RT_CHECK(condition, message): an invariant of the code (not of the user's input) at a contract between
// layers, e.g. "every element is planar and convex", "B is finite after a solve". A failure is a bug: it
// throws rt::CheckFailure naming the source file, line, condition and message, so that tests catch it and
// the CLI reports it apart from input errors. Input problems are InputError, never RT_CHECK.
//
// Active where the build defines RT_ENABLE_CHECKS=1: rt_core's own sources when the CMake option RT_CHECKS is
// on (the default; the dev and asan presets set it; release shares dev's build tree). The checks cost O(n)
// or O(n^2) next to O(n^2) or costlier work; off, the condition is not evaluated at all.
#pragma once

#include <stdexcept>
#include <string>

namespace rt {

class CheckFailure : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

[[noreturn]] void checkFailed(const char* file, int line, const char* condition, const std::string& message);

// Whether rt_core was built with its checks on (tests of the checks skip themselves otherwise, and loops
// that only feed checks are skipped).
bool checksEnabled();

}  // namespace rt

#if defined(RT_ENABLE_CHECKS) && RT_ENABLE_CHECKS
#define RT_CHECK(condition, message)                                                \
  do {                                                                              \
    if (!(condition)) ::rt::checkFailed(__FILE__, __LINE__, #condition, (message)); \
  } while (false)
#else
// Compiled but never evaluated, so that a check cannot rot and its variables still count as used.
#define RT_CHECK(condition, message) \
  do {                               \
    if (false && (condition)) {      \
      static_cast<void>(message);    \
    }                                \
  } while (false)
#endif
