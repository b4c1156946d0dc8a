// For the tests of core/vector_state.h: leaves the upper halves of the YMM registers in use, as a library
// returning from AVX code without `vzeroupper` does. Nothing where the CPU has no AVX (the tests skip there:
// upperVectorStateInUse() answers -1).
#pragma once

namespace rt::test {

inline void dirtyUpperVectorState() {
#if defined(__x86_64__) || defined(__i386__)
  __asm__ volatile(
      "vpcmpeqd %%xmm7, %%xmm7, %%xmm7\n\t"
      "vinsertf128 $1, %%xmm7, %%ymm7, %%ymm7" ::
          : "xmm7");
#endif
}

}  // namespace rt::test
