#include "core/brdf_integrals.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace rt {
namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

double directionalAlbedo(const Brdf& brdf, const Vec3& wi, int rings, int sectors) {
  const double dTheta = 0.5 * kPi / rings, dPhi = 2 * kPi / sectors;
  double sum = 0;
  for (int a = 0; a < rings; ++a) {
    const double theta = (a + 0.5) * dTheta;
    const double weight = std::cos(theta) * std::sin(theta) * dTheta * dPhi;
    double ring = 0;
    for (int b = 0; b < sectors; ++b) ring += evaluateBrdf(brdf, wi, directionAt(theta, (b + 0.5) * dPhi));
    sum += ring * weight;
  }
  return sum + deltaReflectance(brdf, wi);
}

double largestAlbedo(const Brdf& brdf, int rings, int sectors) {
  double largest = 0;
  for (int degrees = 0; degrees < 90; ++degrees)
    for (double phi : {0.0, 0.5 * kPi})
      largest =
          std::max(largest, directionalAlbedo(brdf, directionAt(degrees * kPi / 180, phi), rings, sectors));
  return largest;
}

double reciprocityError(const Brdf& brdf, int pairs, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // Uniform directions on the hemisphere: cos(theta) uniform in (0, 1], phi uniform.
  auto direction = [&] { return directionAt(std::acos(1 - uniform(random)), 2 * kPi * uniform(random)); };
  double worst = 0;
  for (int k = 0; k < pairs; ++k) {
    const Vec3 wi = direction(), wo = direction();
    const double forward = evaluateBrdf(brdf, wi, wo), backward = evaluateBrdf(brdf, wo, wi);
    const double scale = std::max(forward, backward);
    if (scale > 0) worst = std::max(worst, std::abs(forward - backward) / scale);
  }
  return worst;
}

}  // namespace rt
