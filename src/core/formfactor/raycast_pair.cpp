#include "core/formfactor/raycast_pair.h"

#include <algorithm>
#include <vector>

#include "core/formfactor/analytic.h"
#include "core/formfactor/sampling.h"
#include "core/formfactor/visibility.h"

namespace rt {

PairResult estimateRaycastPair(const Mesh& mesh, const PairVisibility& visibility, int i, int j, int samples,
                               std::uint64_t seed) {
  PairResult result;
  const ConvexPolygon a = elementPolygon(mesh, i), b = elementPolygon(mesh, j);
  const Vec3& normalI = mesh.elements[i].normal;
  const Vec3& normalJ = mesh.elements[j].normal;
  const double areaJ = mesh.elements[j].area;
  result.needsVisibility = visibility.mayBeOccluded(i, j);
  PairRandom random(seed, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j));
  // y_k's stratum is a random permutation of x_k's: a fixed shift (stratum k + s) would make y_k a translated
  // copy of x_k, so that all N pairs together were worth about one independent sample of the kernel.
  thread_local std::vector<int> strataOfJ;
  if (result.needsVisibility) shuffledStrata(samples, random, strataOfJ);
  const StrataGrid grid(samples);
  const PolygonSampler onI(a.v.data(), a.count), onJ(b.v.data(), b.count);
  double sum = 0;
  for (int k = 0; k < samples; ++k) {
    const Vec2 s = grid.sample(k, random);
    const Vec3 x = onI.point(s.x(), s.y());
    double value = pointToPolygonFormFactor(x, normalI, b.v.data(), b.count);
    if (result.needsVisibility && value > 0) {
      const Vec2 t = grid.sample(strataOfJ[static_cast<std::size_t>(k)], random);
      const Vec3 y = onJ.point(t.x(), t.y());
      ++result.rays;
      if (!visibility.rays().visible(x, y, i, j)) value -= areaJ * pointToPointKernel(x, normalI, y, normalJ);
    }
    sum += value;
  }
  result.value = std::max(0.0, sum / samples);
  return result;
}

}  // namespace rt
