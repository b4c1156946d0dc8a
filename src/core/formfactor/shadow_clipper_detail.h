// Small helpers shared by the shadow clipper's two files (shadow_clipper.cpp: clipping; shadow_proofs.cpp:
// the proofs that a receiver is wholly hidden and the probes for shadows the samples miss).
#pragma once

#include <algorithm>

#include "core/formfactor/shadow_clipper.h"

namespace rt::shadow_detail {

inline Vec3 centreOf(const SmallPolygon& p) {
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < p.count; ++k) c += p.v[static_cast<std::size_t>(k)];
  return c / std::max(1, p.count);
}

// Only the corners in use: a SmallPolygon holds room for 32, and whole copies cost more than the clipping.
inline void copyPolygon(const SmallPolygon& from, SmallPolygon& to) {
  to.count = from.count;
  std::copy_n(from.v.begin(), from.count, to.v.begin());
}

}  // namespace rt::shadow_detail
