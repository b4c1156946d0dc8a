// Visibility queries on a mesh: one scene of all elements as triangles, cast by Embree 3 where the build has
// it and by the core's own bounding-volume hierarchy elsewhere (formfactor/ray_caster.h). Public header: no
// Embree types.
#pragma once

#include <memory>

#include "core/mesh.h"

namespace rt {

struct RayHit {
  int element = -1;  // -1: the ray escaped
  double distance = 0;
  bool frontSide = false;  // hit the side the element faces (the only side that receives)
};

// Which back end casts the rays: `automatic` is Embree where the build has it, else the portable one.
enum class RayBackend { automatic, embree, portable };

class RayScene {
 public:
  // Throws std::invalid_argument for `embree` in a build without it (rayBackendAvailable says which).
  explicit RayScene(const Mesh& mesh, RayBackend backend = RayBackend::automatic);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // True when the open segment from `from` to `to` crosses no element other than `ignoreA`/`ignoreB` (the two
  // ends' own elements, which a ray leaving or reaching them must not count as occluders; -1 for an end on
  // no element). Thread-safe.
  bool visible(const Vec3& from, const Vec3& to, int ignoreA, int ignoreB) const;
  // First element hit along origin + t direction (direction unit), skipping element `ignore` and the elements
  // in its plane (-1: skip none). Thread-safe.
  RayHit firstHit(const Vec3& origin, const Vec3& direction, int ignore) const;
  // A classic ray tracer's queries: nothing is skipped at the ray's start, and hits count only from `tnear`
  // on, the tracer's self-intersection epsilon (0 lets a ray hit the surface it leaves, at a distance of
  // rounding error). visibleAfter skips the far end's element `ignoreTo` (and its plane). Thread-safe.
  bool visibleAfter(const Vec3& from, const Vec3& to, double tnear, int ignoreTo) const;
  RayHit firstHitAfter(const Vec3& origin, const Vec3& direction, double tnear) const;
  double sceneSize() const { return size_; }
  RayBackend backend() const { return backend_; }

 private:
  bool unoccluded(const Vec3& from, const Vec3& to, float tnear, int ignoreA, int ignoreB) const;
  RayHit nearest(const Vec3& origin, const Vec3& direction, float tnear, int ignore) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
  double size_ = 1;
  RayBackend backend_ = RayBackend::portable;
};

bool rayBackendAvailable(RayBackend backend);

}  // namespace rt
