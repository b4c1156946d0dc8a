#include "core/solvers/line_shooting.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include "core/formfactor/ray_scene.h"
#include "core/formfactor/sampling.h"
#include "core/parallel.h"
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
    parallelForChunks(0, size, {.grain = std::size_t(1) << 16}, [this](std::size_t begin, std::size_t end) {
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

Eigen::RowVector3d constantControl(const RgbField& radiosity, const Eigen::VectorXd& areas) {
  Eigen::RowVector3d beta = Eigen::RowVector3d::Zero();
  const auto n = radiosity.rows();
  if (n == 0 || areas.size() != n) return beta;
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  for (int c = 0; c < 3; ++c) {
    for (Eigen::Index j = 0; j < n; ++j) order[std::size_t(j)] = j;
    std::sort(order.begin(), order.end(),
              [&](Eigen::Index a, Eigen::Index b) { return radiosity(a, c) < radiosity(b, c); });
    const double half = 0.5 * areas.sum();
    double below = 0.0;
    for (const Eigen::Index j : order) {
      below += areas(j);
      if (below >= half) {
        beta(c) = radiosity(j, c);
        break;
      }
    }
  }
  return beta;
}

LineShooter::LineShooter(const Mesh& mesh) : impl_(std::make_unique<Impl>(mesh)) {}
LineShooter::~LineShooter() = default;

namespace {

// The numbers of ray r. Random rays take five from the chunk's stream: the source, two for the origin, two
// for the direction. Sobol rays are point r of the round's scrambled 4-dimensional set: the first number
// picks the source and, where it falls within the source's share, gives the origin's first coordinate, so
// that the origins over all sources are one evenly spread 2-dimensional set (a fifth, independent dimension
// would spread them less evenly for the same points).
class RayNumbers {
 public:
  RayNumbers(LineSampling sampling, std::uint64_t seed, int round, long chunk, long first)
      : random_(seed, static_cast<std::uint64_t>(round), static_cast<std::uint64_t>(chunk)) {
    if (sampling == LineSampling::Sobol) {
      sobol_ = std::make_unique<ScrambledSobol>(4, seed, static_cast<std::uint64_t>(round));
      sobol_->start(static_cast<std::uint64_t>(first));
    }
  }
  bool sobol() const { return sobol_ != nullptr; }
  void next(double* u) {
    if (sobol_) return sobol_->next(u);
    for (int d = 0; d < 5; ++d) u[d] = random_.uniform();
  }

 private:
  PairRandom random_;
  std::unique_ptr<ScrambledSobol> sobol_;
};

}  // namespace

LineRound LineShooter::shoot(const RgbField& radiosity, long rays, std::uint64_t seed, int round,
                             const LineShot& how) {
  Impl& s = *impl_;
  const auto n = static_cast<Eigen::Index>(s.mesh.size());
  LineRound out;
  out.received = RgbField::Zero(n, 3);
  out.sumVariance = RgbField::Zero(n, 3);
  // What each element shoots, per channel and signed, and the absolute power it is sampled by.
  const RgbField shooting = radiosity.rowwise() - how.control;
  double total = 0.0;
  Eigen::Index lastSource = -1;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double power = shooting.row(j).cwiseAbs().sum() * s.areas(j);
    if (power > 0.0) lastSource = j;
    s.cumulative[std::size_t(j)] = total += power;
  }
  if (total <= 0.0 || lastSource < 0 || rays <= 0) return out;
  s.scores.clear();
  std::atomic<std::int64_t> lost{0};
  const long chunks = (rays + kChunk - 1) / kChunk;
  parallelForChunks(0, static_cast<std::size_t>(chunks), {.grain = 1}, [&](std::size_t lo, std::size_t hi) {
    std::int64_t lostHere = 0;
    for (long chunk = static_cast<long>(lo); chunk != static_cast<long>(hi); ++chunk) {
      RayNumbers numbers(how.sampling, seed, round, chunk, chunk * kChunk);
      for (long r = chunk * kChunk, end = std::min(rays, r + kChunk); r < end; ++r) {
        double u[5];
        numbers.next(u);
        const std::size_t picked = solver_detail::sampleCumulative(s.cumulative, u[0] * total);
        auto j = static_cast<Eigen::Index>(std::min(picked, std::size_t(n - 1)));
        if (!(shooting.row(j).cwiseAbs().sum() > 0.0)) j = lastSource;  // rounding at the top of the sum
        double p[4] = {u[1], u[2], u[3], u[4]};                         // origin, then direction
        if (numbers.sobol()) {
          const double below = j > 0 ? s.cumulative[std::size_t(j - 1)] : 0.0;
          const double share = s.cumulative[std::size_t(j)] - below;
          const double within = share > 0.0 ? (u[0] * total - below) / share : 0.5;
          p[0] = std::clamp(within, 0.0, 0x1.fffffffffffffp-1);
          p[1] = u[1];
          p[2] = u[2];
          p[3] = u[3];
        }
        const Source source = sourceOf(s.mesh, j);
        const Vec3 origin = pointOnPolygon(source.corners, source.count, p[0], p[1]);
        const RayHit hit =
            s.scene.firstHit(origin, cosineDirection(source.normal, p[2], p[3]), static_cast<int>(j));
        // The ray's power is total / rays, split over the channels as the source's shot radiosity is.
        const Eigen::RowVector3d fraction = shooting.row(j) / shooting.row(j).cwiseAbs().sum();
        if (hit.element < 0 || !hit.frontSide) {
          lostHere += std::llround(fraction.sum() * kFixed);
          continue;
        }
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
  out.lost = double(lost.load()) / kFixed * perRay;
  for (Eigen::Index j = 0; j < n; ++j)
    for (int c = 0; c < 3; ++c) {
      const double in = double(s.scores.at(j, c)) / kFixed * perRay;
      const double squares = double(s.scores.at(j, 3 + c)) / kFixed * perRay * perRay;
      out.received(j, c) = in;
      // Variance of a sum of `rays` independent scores, estimated from the same scores (for Sobol rays,
      // which are not independent, an upper estimate).
      out.sumVariance(j, c) = std::max(0.0, squares - in * in / double(rays));
    }
  return out;
}

Eigen::VectorXd LineShooter::rowSums(int perElement, std::uint64_t seed) {
  Impl& s = *impl_;
  const auto n = static_cast<Eigen::Index>(s.mesh.size());
  Eigen::VectorXd sums = Eigen::VectorXd::Zero(n);
  if (perElement < 1) return sums;
  parallelFor(Eigen::Index(0), n, [&](Eigen::Index j) {
    const Source source = sourceOf(s.mesh, j);
    // Its own scrambled set per element, so that every element's lines are evenly spread over it.
    ScrambledSobol sobol(4, seed, 0x726f7773ull + static_cast<std::uint64_t>(j));
    sobol.start(0);
    int front = 0;
    for (int k = 0; k < perElement; ++k) {
      double u[4];
      sobol.next(u);
      const Vec3 origin = pointOnPolygon(source.corners, source.count, u[0], u[1]);
      const RayHit hit =
          s.scene.firstHit(origin, cosineDirection(source.normal, u[2], u[3]), static_cast<int>(j));
      if (hit.element >= 0 && hit.frontSide) ++front;
    }
    sums(j) = double(front) / double(perElement);
  });
  return sums;
}

}  // namespace rt
