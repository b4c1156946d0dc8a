// The ray-casting back ends under RayScene (internal to the core): Embree where the build has it (the native
// build), and the core's own bounding-volume hierarchy everywhere (the WebAssembly build, which has no
// Embree, and the test that holds the two to the same hits). Both take the same float triangles and the same
// filter, so RayScene's rules (which elements a ray passes through, the front-side retry) are written once.
//
// Back ends considered for the portable build: Embree itself (x86/ARM SIMD kernels, no WebAssembly port in
// Debian 12), CGAL's AABB tree (Debian's libcgal-dev, but the core must not use CGAL and its exact kernels
// are far slower), nanort and madmann91/bvh (maintained header-only BVHs, packaged neither in Debian 12 nor
// on npm as C++), three-mesh-bvh (npm, JavaScript: the core's rays are cast from C++). None fits, hence
// ray_caster_bvh.cpp.
#pragma once

#include <memory>
#include <vector>

#include "core/vec.h"

namespace rt {

// Which candidate hits count: not the two ends' own elements, not the elements in their planes and, with
// `frontOnlyNormals`, not an element met from behind.
struct RayFilter {
  const std::vector<int>* primitiveElement = nullptr;
  const std::vector<int>* elementPlane = nullptr;
  const std::vector<Vec3>* frontOnlyNormals = nullptr;
  int ignoreA = -1, ignoreB = -1;

  bool accepts(unsigned primitive, float dx, float dy, float dz) const;
};

// One ray in the back ends' precision: origin, unit direction, the interval of t that counts.
struct FloatRay {
  float origin[3];
  float direction[3];
  float tnear, tfar;
};

class RayCaster {
 public:
  virtual ~RayCaster() = default;
  // True when an accepted hit lies within [tnear, tfar].
  virtual bool occluded(const FloatRay& ray, const RayFilter& filter) const = 0;
  // The nearest accepted hit within [tnear, tfar]: its triangle (-1: none) and its t.
  virtual int nearest(const FloatRay& ray, const RayFilter& filter, float& t) const = 0;
};

// Triangles as float xyz triples and three vertex indices each. makeEmbreeCaster returns nullptr in a build
// without Embree.
std::unique_ptr<RayCaster> makeEmbreeCaster(const std::vector<float>& vertices,
                                            const std::vector<unsigned>& triangles);
std::unique_ptr<RayCaster> makeBvhCaster(const std::vector<float>& vertices,
                                         const std::vector<unsigned>& triangles);

}  // namespace rt
