#include "core/pathtrace/local_illumination.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/brdf.h"
#include "core/formfactor/sampling.h"
#include "core/parallel.h"
#include "core/pathtrace/path_tracer.h"

namespace rt {
namespace {

// Any orthonormal frame with z along n (the Phong lobe is isotropic: the tangent's direction does not
// matter).
struct Frame {
  Vec3 x, y, z;
  explicit Frame(const Vec3& n) : z(n) {
    x = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    y = z.cross(x);
  }
  Vec3 local(const Vec3& w) const { return {w.dot(x), w.dot(y), w.dot(z)}; }
};

}  // namespace

LocalIlluminationParts renderLocalIlluminationParts(const TracingScene& scene, const Camera& camera,
                                                    int width, int height,
                                                    const LocalIlluminationOptions& o) {
  LocalIlluminationParts parts{RgbImage(width, height), RgbImage(width, height)};
  const Mesh& mesh = scene.mesh();
  const RayScene& rays = scene.rays();
  const int pixelSamples = std::max(1, o.pixelSamples), lightSamples = std::max(1, o.lightSamples);
  const StrataGrid pixelGrid(pixelSamples), lightGrid(lightSamples);
  parallelForChunks(0, static_cast<std::size_t>(height), {}, [&](std::size_t lo, std::size_t hi) {
    for (int y = static_cast<int>(lo); y != static_cast<int>(hi); ++y)
      for (int x = 0; x < width; ++x) {
        PairRandom random(11, static_cast<std::uint64_t>(y) * width + x, 0);
        Rgb sum = Rgb::Zero(), reflectance = Rgb::Zero();
        for (int k = 0; k < pixelSamples; ++k) {
          const Vec2 jitter = pixelGrid.sample(k, random);
          const Vec3 direction = cameraRay(camera, width, height, x + jitter.x(), y + jitter.y());
          const RayHit hit = rays.firstHit(camera.position, direction, -1);
          if (hit.element < 0 || !hit.frontSide) continue;
          const auto e = static_cast<Eigen::Index>(hit.element);
          const Rgb emission = mesh.emission.row(e).transpose().array();
          if ((emission > 0).any()) {
            sum += emission;
            continue;
          }
          const Rgb rho = mesh.reflectance.row(e).transpose().array();
          const Vec3 point = camera.position + hit.distance * direction;
          const Frame frame(mesh.elements[static_cast<std::size_t>(e)].normal);
          const Vec3 wo = frame.local(-direction);
          Rgb direct = Rgb::Zero();
          for (int s = 0; s < lightSamples; ++s) {
            const Vec2 uv = lightGrid.sample(s, random);
            const LightSample light = scene.sampleLight(random.uniform(), uv.x(), uv.y());
            if (!(light.weight > 0)) continue;
            const Vec3 toLight = light.point - point;
            const double r2 = toLight.squaredNorm();
            const Vec3 wiWorld = toLight / std::sqrt(r2);
            const double cosLight = -wiWorld.dot(light.normal);
            const Vec3 wi = frame.local(wiWorld);
            if (!(wi.z() > 0) || !(cosLight > 0)) continue;
            if (!rays.visible(point, light.point, hit.element, light.element)) continue;
            // pi f_r L_e cos(theta) d(omega), with L_e = E / pi and d(omega) = cos(theta') dA / r^2.
            const double geometry = wi.z() * cosLight / r2 * light.weight;
            Rgb f;
            for (int ch = 0; ch < 3; ++ch)
              f[ch] = evaluateBrdf(makeBrdf(BrdfModel::Phong, rho[ch], o.specularFraction, o.exponent, 1), wi,
                                   wo);
            direct += f * light.emission * geometry;
          }
          sum += direct / lightSamples;
          reflectance += rho;
        }
        parts.direct.at(x, y) = sum / pixelSamples;
        parts.reflectance.at(x, y) = reflectance / pixelSamples;
      }
  });
  return parts;
}

RgbImage withAmbient(const LocalIlluminationParts& parts, const Rgb& ambient) {
  RgbImage image = parts.direct;
  for (std::size_t k = 0; k < image.pixels.size(); ++k)
    image.pixels[k] += parts.reflectance.pixels[k] * ambient;
  return image;
}

RgbImage renderLocalIllumination(const TracingScene& scene, const Camera& camera, int width, int height,
                                 const LocalIlluminationOptions& o) {
  return withAmbient(renderLocalIlluminationParts(scene, camera, width, height, o), o.ambient);
}

}  // namespace rt
