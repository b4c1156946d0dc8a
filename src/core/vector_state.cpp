#include "core/vector_state.h"

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

namespace rt {
namespace {

#if defined(__x86_64__) || defined(__i386__)
// AVX usable: the CPU has it and the operating system saves the YMM state (OSXSAVE, XCR0 bits 1 and 2).
bool detectAvx() {
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  if (!__get_cpuid(1, &eax, &ebx, &ecx, &edx)) return false;
  const bool avx = (ecx & (1u << 28)) != 0, osxsave = (ecx & (1u << 27)) != 0;
  if (!avx || !osxsave) return false;
  unsigned low = 0, high = 0;
  __asm__ volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(0));
  return (low & 0x6u) == 0x6u;
}

// XGETBV with ECX = 1 (XINUSE) exists: CPUID leaf 0xD, sub-leaf 1, EAX bit 2.
bool detectXinuse() {
  if (!detectAvx()) return false;
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  if (!__get_cpuid_count(0xD, 1, &eax, &ebx, &ecx, &edx)) return false;
  return (eax & (1u << 2)) != 0;
}

bool haveAvx() {
  static const bool have = detectAvx();
  return have;
}
#endif

}  // namespace

void clearUpperVectorState() {
#if defined(__x86_64__) || defined(__i386__)
  // The assembler takes the instruction whatever the compiler's target; it only runs where AVX exists.
  if (haveAvx()) __asm__ volatile("vzeroupper" ::: "memory");
#endif
}

int upperVectorStateInUse() {
#if defined(__x86_64__) || defined(__i386__)
  static const bool xinuse = detectXinuse();
  if (!xinuse) return -1;
  unsigned low = 0, high = 0;
  __asm__ volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(1));
  return (low & 0x4u) != 0 ? 1 : 0;  // state component 2: the YMM registers' upper halves
#else
  return -1;
#endif
}

}  // namespace rt
