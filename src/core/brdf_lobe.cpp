#include "core/brdf_lobe.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/polygon.h"

namespace rt {
namespace {

constexpr double kPi = std::numbers::pi;

// An orthonormal pair perpendicular to the unit vector a.
std::pair<Vec3, Vec3> perpendiculars(const Vec3& a) {
  const Vec3 u = (std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(a).normalized();
  return {u, a.cross(u)};
}

double lobeRadius(const Brdf& brdf, const Vec3& wi, const Vec3& wo) {
  return wo.z() > 0 ? evaluateBrdf(brdf, wi, wo) * wo.z() : 0.0;
}

}  // namespace

std::vector<Polygon> prism(const Vec3& from, const Vec3& to, double radius) {
  const Vec3 axis = (to - from).normalized();
  const auto [u, v] = perpendiculars(axis);
  const Vec3 corners[4] = {radius * (u + v), radius * (-u + v), radius * (-u - v), radius * (u - v)};
  std::vector<Polygon> sides;
  for (int k = 0; k < 4; ++k) {
    const Vec3 a = corners[k], b = corners[(k + 1) % 4];
    Polygon side{from + a, to + a, to + b, from + b};
    const Vec3 middle = 0.5 * (a + b);
    if (newellNormal(side).dot(middle) < 0) std::reverse(side.begin(), side.end());
    sides.push_back(side);
  }
  return sides;
}

BrdfLobe brdfLobe(const Brdf& brdf, const Vec3& wi, double size, int rings, int sectors) {
  BrdfLobe lobe;
  if (brdf.model == BrdfModel::Mirror) {
    lobe.peak = deltaReflectance(brdf, wi);
    lobe.scale = size;
    lobe.triangles = prism(Vec3::Zero(), lobe.peak * size * mirrorDirection(wi), 0.015 * size);
    lobe.values.assign(lobe.triangles.size(), lobe.peak);
    return lobe;
  }
  const Vec3 axis = brdf.model == BrdfModel::Lambertian ? Vec3::UnitZ() : mirrorDirection(wi);
  // Named copies, not structured bindings: C++20 lambdas may capture those only from clang 16 on.
  const auto frame = perpendiculars(axis);
  const Vec3 u = frame.first, v = frame.second;
  // Ring a at the angle pi (a / rings)^2 from the axis: dense near it, reaching the opposite pole.
  auto direction = [&](int a, int b) {
    const double t = static_cast<double>(a) / rings, beta = kPi * t * t, phi = 2 * kPi * b / sectors;
    return Vec3(std::cos(beta) * axis + std::sin(beta) * (std::cos(phi) * u + std::sin(phi) * v));
  };
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(rings + 1) * sectors);
  for (int a = 0; a <= rings; ++a)
    for (int b = 0; b < sectors; ++b) {
      const Vec3 w = direction(a, b);
      const double r = lobeRadius(brdf, wi, w);
      lobe.peak = std::max(lobe.peak, r);
      points.push_back(r * w);
    }
  lobe.scale = lobe.peak > 0 ? size / lobe.peak : 0.0;
  for (Vec3& p : points) p *= lobe.scale;
  const auto at = [&](int a, int b) { return points[static_cast<std::size_t>(a) * sectors + (b % sectors)]; };
  const double smallest = 1e-8 * size * size;
  auto add = [&](const Vec3& p, const Vec3& q, const Vec3& r) {
    Polygon t{p, q, r};
    if (polygonArea(t) < smallest) return;  // where the lobe meets the surface or the axis
    const Vec3 centre = (p + q + r) / 3;
    if (newellNormal(t).dot(centre) < 0) std::swap(t[1], t[2]);
    lobe.triangles.push_back(t);
    lobe.values.push_back(centre.norm() / std::max(lobe.scale, 1e-300));
  };
  for (int a = 0; a < rings; ++a)
    for (int b = 0; b < sectors; ++b) {
      add(at(a, b), at(a + 1, b), at(a + 1, b + 1));
      add(at(a, b), at(a + 1, b + 1), at(a, b + 1));
    }
  return lobe;
}

}  // namespace rt
