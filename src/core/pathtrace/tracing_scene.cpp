#include "core/pathtrace/tracing_scene.h"

#include <algorithm>

namespace rt {

TracingScene::TracingScene(const Scene& scene) : scene_(scene), mesh_(buildMesh(scene, MeshOptions{})) {
  rays_ = std::make_unique<RayScene>(mesh_);
  patchElement_.assign(scene.patches.size(), -1);
  for (std::size_t e = mesh_.size(); e-- > 0;)
    patchElement_[static_cast<std::size_t>(mesh_.elements[e].patch)] = static_cast<int>(e);
  tolerance_ = 1e-6 * rays_->sceneSize();
  double total = 0;
  for (std::size_t e = 0; e < mesh_.size(); ++e) {
    const auto row = static_cast<Eigen::Index>(e);
    const Rgb emission = mesh_.emission.row(row).transpose().array();
    if (!(emission > 0.0).any()) continue;
    const Element& element = mesh_.elements[e];
    emitters_.push_back(
        {static_cast<int>(e), mesh_.polygon(static_cast<int>(e)), element.normal, element.area, emission});
    total += emission.sum() * element.area;
    cumulative_.push_back(total);
  }
  // The samplers keep pointers into the emitters' polygons: made once the vector no longer moves.
  for (const Emitter& emitter : emitters_)
    samplers_.emplace_back(emitter.polygon.data(), static_cast<int>(emitter.polygon.size()));
  for (double& c : cumulative_) c /= total;
  density_.assign(mesh_.size(), 0.0);
  for (const Emitter& emitter : emitters_)
    density_[static_cast<std::size_t>(emitter.element)] = emitter.emission.sum() / total;
}

LightSample TracingScene::sampleLight(double pick, double u, double v) const {
  LightSample sample;
  if (emitters_.empty()) return sample;
  const auto found = std::upper_bound(cumulative_.begin(), cumulative_.end(), pick);
  const std::size_t k =
      std::min<std::size_t>(static_cast<std::size_t>(found - cumulative_.begin()), emitters_.size() - 1);
  const double probability = cumulative_[k] - (k > 0 ? cumulative_[k - 1] : 0.0);
  const Emitter& emitter = emitters_[k];
  sample.point = samplers_[k].point(u, v);
  sample.normal = emitter.normal;
  sample.element = emitter.element;
  sample.emission = emitter.emission;
  sample.weight = emitter.area / probability;
  return sample;
}

int TracingScene::locate(const SurfacePoint& point) const {
  // A point on an edge shared by two coplanar patches belongs to either; the first one found is as good.
  for (std::size_t e = 0; e < mesh_.size(); ++e) {
    const Element& element = mesh_.elements[e];
    if (element.normal.dot(point.normal) < 0.999) continue;
    const Polygon polygon = mesh_.polygon(static_cast<int>(e));
    if (std::abs(element.normal.dot(point.position - polygon[0])) > tolerance_) continue;
    bool inside = true;
    for (std::size_t k = 0; k < polygon.size() && inside; ++k) {
      const Vec3& a = polygon[k];
      const Vec3& b = polygon[(k + 1) % polygon.size()];
      // Counter-clockwise seen from the front: the inside is to the left of every edge.
      const Vec3 inward = element.normal.cross(b - a).normalized();
      inside = inward.dot(point.position - a) >= -tolerance_;
    }
    if (inside) return static_cast<int>(e);
  }
  return -1;
}

}  // namespace rt
