#include "core/solvers/line_shooting.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include "core/formfactor/ray_scene.h"
#include "core/formfactor/sampling.h"
#include "core/solvers/solver_support.h"

namespace rt {

namespace {

// Rays per random stream: large enough that seeding costs nothing, small enough for both cores to share
// even the short last rounds.
constexpr long kChunk = 2048;
// Scores are a source's colour fractions (each in [0, 1]) in units of 2^-32: an element can take 2^31
// rays in one round before its sum overflows, and the rounding, 1e-10 of a ray, is far below the noise.
constexpr double kFixed = 4294967296.0;

// Per element: the sums of the scores of the rays that hit it, per channel, and of their squares.
struct Scores {
  explicit Scores(std::size_t n) : values(new std::atomic<std::int64_t>[6 * n]), size(6 * n) {}
  void clear() {
    tbb::parallel_for(std::size_t(0), size, std::size_t(1) << 16, [this](std::size_t begin) {
      const std::size_t end = std::min(size, begin + (std::size_t(1) << 16));
      for (std::size_t k = begin; k < end; ++k) values[k].store(0, std::memory_order_relaxed);
    });
  }
  std::int64_t at(Eigen::Index element, int k) const {
    return values[6 * static_cast<std::size_t>(element) + k].load(std::memory_order_relaxed);
  }
  void add(int element, const std::int64_t score[6]) {
    std::atomic<std::int64_t>* v = &values[6 * static_cast<std::size_t>(element)];
    for (int k = 0; k < 6; ++k)
      if (score[k] != 0) v[k].fetch_add(score[k], std::memory_order_relaxed);
  }
  std::unique_ptr<std::atomic<std::int64_t>[]> values;
  std::size_t size;
};

// One element's corners and unit normal, for drawing ray origins and directions.
struct Source {
  Vec3 corners[8];
  int count = 0;
  Vec3 normal;
};

Source sourceOf(const Mesh& mesh, Eigen::Index j) {
  const Element& e = mesh.elements[static_cast<std::size_t>(j)];
  Source s;
  s.count = static_cast<int>(std::min<std::size_t>(e.vertices.size(), 8));
  for (int k = 0; k < s.count; ++k) s.corners[k] = mesh.vertices[static_cast<std::size_t>(e.vertices[k])];
  s.normal = e.normal.normalized();
  return s;
}

}  // namespace

struct LineShooter::Impl {
  explicit Impl(const Mesh& m)
      : mesh(m), scene(m), areas(m.areas()), scores(m.size()), cumulative(m.size()) {}
  const Mesh& mesh;
  const RayScene scene;
  const Eigen::VectorXd areas;
  Scores scores;
  std::vector<double> cumulative;
};

LineShooter::LineShooter(const Mesh& mesh) : impl_(std::make_unique<Impl>(mesh)) {}
LineShooter::~LineShooter() = default;

LineRound LineShooter::shoot(const RgbField& radiosity, long rays, std::uint64_t seed, int round) {
  Impl& s = *impl_;
  const auto n = static_cast<Eigen::Index>(s.mesh.size());
  LineRound out;
  out.received = RgbField::Zero(n, 3);
  out.sumVariance = RgbField::Zero(n, 3);
  double total = 0.0;
  Eigen::Index lastSource = -1;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double power = radiosity.row(j).sum() * s.areas(j);
    if (power > 0.0) lastSource = j;
    s.cumulative[std::size_t(j)] = total += power;
  }
  if (total <= 0.0 || lastSource < 0 || rays <= 0) return out;
  s.scores.clear();
  std::atomic<long> lost{0};
  const long chunks = (rays + kChunk - 1) / kChunk;
  tbb::parallel_for(tbb::blocked_range<long>(0, chunks, 1), [&](const tbb::blocked_range<long>& range) {
    long lostHere = 0;
    for (long chunk = range.begin(); chunk != range.end(); ++chunk) {
      PairRandom random(seed, static_cast<std::uint64_t>(round), static_cast<std::uint64_t>(chunk));
      for (long r = chunk * kChunk, end = std::min(rays, r + kChunk); r < end; ++r) {
        const std::size_t picked = solver_detail::sampleCumulative(s.cumulative, random.uniform() * total);
        auto j = static_cast<Eigen::Index>(std::min(picked, std::size_t(n - 1)));
        if (!(radiosity.row(j).sum() > 0.0)) j = lastSource;  // rounding at the top of the running sum
        const Source source = sourceOf(s.mesh, j);
        const double u = random.uniform(), v = random.uniform();
        const Vec3 origin = pointOnPolygon(source.corners, source.count, u, v);
        const double a = random.uniform(), b = random.uniform();
        const RayHit hit =
            s.scene.firstHit(origin, cosineDirection(source.normal, a, b), static_cast<int>(j));
        if (hit.element < 0 || !hit.frontSide) {
          ++lostHere;
          continue;
        }
        // The ray's power is total / rays, split over the channels as the source's radiosity is.
        const Eigen::RowVector3d fraction = radiosity.row(j) / radiosity.row(j).sum();
        std::int64_t score[6];
        for (int c = 0; c < 3; ++c) {
          score[c] = std::llround(fraction(c) * kFixed);
          score[3 + c] = std::llround(fraction(c) * fraction(c) * kFixed);
        }
        s.scores.add(hit.element, score);
      }
    }
    lost += lostHere;
  });
  const double perRay = total / double(rays);
  out.shot = total;
  out.rays = rays;
  out.lost = double(lost.load()) * perRay;
  for (Eigen::Index j = 0; j < n; ++j)
    for (int c = 0; c < 3; ++c) {
      const double in = double(s.scores.at(j, c)) / kFixed * perRay;
      const double squares = double(s.scores.at(j, 3 + c)) / kFixed * perRay * perRay;
      out.received(j, c) = in;
      // Variance of a sum of `rays` independent scores, estimated from the same scores.
      out.sumVariance(j, c) = std::max(0.0, squares - in * in / double(rays));
    }
  return out;
}

}  // namespace rt
