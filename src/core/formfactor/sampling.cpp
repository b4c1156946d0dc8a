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

StrataGrid::StrataGrid(int n)
    : columns_(std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(n)))))),
      rows_(std::max(1, n / columns_)) {}

Vec2 StrataGrid::sample(int k, PairRandom& random) const {
  if (k >= columns_ * rows_) return {random.uniform(), random.uniform()};
  const int column = k % columns_, row = k / columns_;
  return {(column + random.uniform()) / columns_, (row + random.uniform()) / rows_};
}

Vec2 jitteredSample(int k, int n, PairRandom& random) {
  return StrataGrid(n).sample(k, random);
}

void shuffledStrata(int n, PairRandom& random, std::vector<int>& order) {
  order.resize(static_cast<std::size_t>(std::max(0, n)));
  for (int k = 0; k < n; ++k) order[static_cast<std::size_t>(k)] = k;
  for (int k = n - 1; k > 0; --k)  // Fisher-Yates
    std::swap(order[static_cast<std::size_t>(k)],
              order[static_cast<std::size_t>(random.next() % static_cast<std::uint64_t>(k + 1))]);
}

PaddedStrata::PaddedStrata(int n, int dimensions, PairRandom& random)
    : grid_(n), orders_(static_cast<std::size_t>(std::max(0, dimensions))) {
  for (auto& order : orders_) shuffledStrata(n, random, order);
}

Vec2 PaddedStrata::sample(int dimension, int k, PairRandom& random) const {
  if (dimension < 0 || dimension >= static_cast<int>(orders_.size()) ||
      k >= static_cast<int>(orders_[static_cast<std::size_t>(dimension)].size()))
    return {random.uniform(), random.uniform()};
  return grid_.sample(orders_[static_cast<std::size_t>(dimension)][static_cast<std::size_t>(k)], random);
}

PolygonSampler::PolygonSampler(const Vec3* polygon, int count)
    : polygon_(polygon), triangles_(std::clamp(count - 2, 1, 16)) {
  if (triangles_ == 1) return;
  for (int t = 0; t < triangles_; ++t) {
    areas_[t] = (polygon[t + 1] - polygon[0]).cross(polygon[t + 2] - polygon[0]).norm();
    total_ += areas_[t];
  }
}

Vec3 PolygonSampler::point(double u, double v) const {
  int chosen = 0;
  if (triangles_ > 1) {
    double target = u * total_;
    for (chosen = 0; chosen + 1 < triangles_ && target >= areas_[chosen]; ++chosen) target -= areas_[chosen];
    u = areas_[chosen] > 0 ? std::clamp(target / areas_[chosen], 0.0, 1.0) : 0.5;
  }
  const double s = std::sqrt(u);
  const Vec3& a = polygon_[0];
  const Vec3& b = polygon_[chosen + 1];
  const Vec3& c = polygon_[chosen + 2];
  return (1 - s) * a + s * (1 - v) * b + s * v * c;
}

Vec3 pointOnPolygon(const Vec3* polygon, int count, double u, double v) {
  return PolygonSampler(polygon, count).point(u, v);
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
