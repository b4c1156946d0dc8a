// An array of N slots with the part of SmallBuffer's interface a polygon uses (small_buffer.h: data(), [],
// reserve()) that never grows: the convex polygons whose corner count is bounded by what makes them (a
// quadrature panel has 3 or 4 corners), copied by the million where a heap pointer and a destructor would
// cost more than the corners.
//
// Asking for more room than N is a bug of the caller, never a silent loss of corners: reserve() fails with
// CheckFailure naming the capacity, whether or not the build has its RT_CHECKs on.
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "core/check.h"

namespace rt {

template <class T, int N>
class FixedBuffer {
 public:
  static constexpr int kInline = N;

  T* data() { return slots_.data(); }
  const T* data() const { return slots_.data(); }
  T& operator[](std::size_t k) { return slots_[k]; }
  const T& operator[](std::size_t k) const { return slots_[k]; }

  // Room for `n` entries: there is or it fails (see above).
  void reserve(int n) {
    if (n > N)
      checkFailed(__FILE__, __LINE__, "n <= N",
                  "a fixed buffer of " + std::to_string(N) + " slots asked for " + std::to_string(n));
  }

 private:
  std::array<T, N> slots_;
};

}  // namespace rt
