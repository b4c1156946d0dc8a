// A scene prepared for tracing rays: one element per patch in Embree, the emitters with their areas and a
// way to sample them, and the lookup of the patch a query point lies on. The path tracer and the two-pass
// point query share it, so that both see the same geometry, materials and lights.
#pragma once

#include <memory>
#include <vector>

#include "core/formfactor/ray_scene.h"
#include "core/formfactor/sampling.h"
#include "core/mesh.h"
#include "core/scene.h"

namespace rt {

// A point on a surface and the unit normal of the side it receives on.
struct SurfacePoint {
  Vec3 position;
  Vec3 normal;
};

// One point sampled on an emitter, with the weight that makes E K(x, y) * weight an unbiased estimate of the
// irradiance from all emitters.
struct LightSample {
  Vec3 point;
  Vec3 normal;
  int element = -1;
  Rgb emission = Rgb::Zero();
  double weight = 0;  // area of the emitter / probability of picking it
};

struct Emitter {
  int element = -1;  // element of the tracing mesh (one per patch)
  Polygon polygon;
  Vec3 normal;
  double area = 0;
  Rgb emission = Rgb::Zero();
};

class TracingScene {
 public:
  explicit TracingScene(const Scene& scene);
  TracingScene(const TracingScene&) = delete;
  TracingScene& operator=(const TracingScene&) = delete;

  const Scene& scene() const { return scene_; }
  const Mesh& mesh() const { return mesh_; }
  const RayScene& rays() const { return *rays_; }
  const std::vector<Emitter>& emitters() const { return emitters_; }

  // Picks an emitter with probability in proportion to its emitted power (sum over channels of E A) with
  // `pick`, then a uniform point on it from (u, v). No emitter: weight 0.
  LightSample sampleLight(double pick, double u, double v) const;

  // The element (= patch) that `point` lies on and faces the way `normal` does, within 1e-6 of the scene's
  // size; -1 when there is none (a point in the air, or a normal that matches no surface there).
  int locate(const SurfacePoint& point) const;

  // The probability density, per unit area, with which sampleLight picks a point of element `element` (0 for
  // a non-emitter): what multiple importance sampling needs to weigh a bounce that reaches an emitter.
  double lightDensity(int element) const { return density_[static_cast<std::size_t>(element)]; }

  // The patch of the scene behind element `element` of the tracing mesh.
  int patchOf(int element) const { return mesh_.elements[static_cast<std::size_t>(element)].patch; }
  // An element of the tracing mesh on patch `patch` (its plane is what rays leaving the patch ignore).
  int elementOf(int patch) const { return patchElement_[static_cast<std::size_t>(patch)]; }

 private:
  const Scene& scene_;
  Mesh mesh_;
  std::unique_ptr<RayScene> rays_;
  std::vector<Emitter> emitters_;
  std::vector<PolygonSampler> samplers_;
  std::vector<double> cumulative_;  // picking probabilities, cumulative
  std::vector<double> density_;     // per element
  std::vector<int> patchElement_;   // per patch
  double tolerance_ = 0;
};

}  // namespace rt
