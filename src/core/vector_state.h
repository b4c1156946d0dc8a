// The upper halves of the x86 vector registers, kept clean for the maths library.
//
// Some shared libraries the programs load (Qt's QML stack, pulled in by the typesetter's web engine) run
// 256-bit AVX code in their static initialisers and return without `vzeroupper`. The upper halves of the YMM
// registers then stay "in use" in that thread and in every thread created from it. glibc picks AVX2/FMA
// versions of atan2, log and friends on such CPUs, and on some of them (measured on an Intel Xeon under KVM)
// each call then pays a state transition: atan2 took 144 ns instead of 20, and the quadrature form factors
// of the 2,400-wall room 5.1 s instead of 2.1 s. One `vzeroupper` per thread before the work restores the
// normal speed; it does not touch any value the program holds in a register across the call.
#pragma once

namespace rt {

// Marks the upper halves of the vector registers unused in the calling thread (`vzeroupper`) where the CPU
// has AVX; nothing elsewhere. Cheap enough to call at the start of every task.
void clearUpperVectorState();

// Whether the calling thread's upper vector state is in use: 1 or 0, or -1 where the CPU cannot tell
// (no XGETBV with ECX = 1, or not x86). For tests.
int upperVectorStateInUse();

}  // namespace rt
