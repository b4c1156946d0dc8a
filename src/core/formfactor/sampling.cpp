#include "core/formfactor/sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rt {

PairRandom::PairRandom(std::uint64_t seed, std::uint64_t i, std::uint64_t j) : state_(seed) {
  // Mix the indices in through the generator itself so nearby (i, j) give unrelated streams.
  state_ ^= 0x9E3779B97F4A7C15ull * (i + 1);
  next();
  state_ ^= 0xC2B2AE3D27D4EB4Full * (j + 1);
  next();
}

std::uint64_t PairRandom::next() {
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double PairRandom::uniform() {
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

Vec2 jitteredSample(int k, int n, PairRandom& random) {
  const int columns = std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(n)))));
  const int rows = std::max(1, n / columns);
  if (k >= columns * rows) return {random.uniform(), random.uniform()};
  const int column = k % columns, row = k / columns;
  return {(column + random.uniform()) / columns, (row + random.uniform()) / rows};
}

void shuffledStrata(int n, PairRandom& random, std::vector<int>& order) {
  order.resize(static_cast<std::size_t>(std::max(0, n)));
  for (int k = 0; k < n; ++k) order[static_cast<std::size_t>(k)] = k;
  for (int k = n - 1; k > 0; --k)  // Fisher-Yates
    std::swap(order[static_cast<std::size_t>(k)],
              order[static_cast<std::size_t>(random.next() % static_cast<std::uint64_t>(k + 1))]);
}

Vec3 pointOnPolygon(const Vec3* polygon, int count, double u, double v) {
  const std::size_t triangles = static_cast<std::size_t>(count) - 2;
  std::size_t chosen = 0;
  if (triangles > 1) {
    double total = 0;
    double areas[16];
    const std::size_t counted = std::min<std::size_t>(triangles, 16);
    for (std::size_t t = 0; t < counted; ++t) {
      areas[t] = (polygon[t + 1] - polygon[0]).cross(polygon[t + 2] - polygon[0]).norm();
      total += areas[t];
    }
    double target = u * total;
    for (chosen = 0; chosen + 1 < counted && target >= areas[chosen]; ++chosen) target -= areas[chosen];
    u = areas[chosen] > 0 ? std::clamp(target / areas[chosen], 0.0, 1.0) : 0.5;
  }
  const double s = std::sqrt(u);
  const Vec3& a = polygon[0];
  const Vec3& b = polygon[chosen + 1];
  const Vec3& c = polygon[chosen + 2];
  return (1 - s) * a + s * (1 - v) * b + s * v * c;
}

Vec3 cosineDirection(const Vec3& normal, double u, double v) {
  const double radius = std::sqrt(u), angle = 2 * std::numbers::pi * v;
  const double x = radius * std::cos(angle), y = radius * std::sin(angle);
  const double z = std::sqrt(std::max(0.0, 1 - u));
  // Any orthonormal frame about the normal (Duff et al.'s branchless construction).
  const double sign = std::copysign(1.0, normal.z());
  const double a = -1.0 / (sign + normal.z());
  const double b = normal.x() * normal.y() * a;
  const Vec3 tangent(1 + sign * normal.x() * normal.x() * a, sign * b, -sign * normal.x());
  const Vec3 bitangent(b, sign + normal.y() * normal.y() * a, -normal.y());
  return x * tangent + y * bitangent + z * normal;
}

}  // namespace rt
