#include "core/solvers/local_lines_solver.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <vector>

#include "core/formfactor/ray_scene.h"
#include "core/formfactor/sampling.h"
#include "core/solvers/solver_support.h"

namespace rt {

namespace {

using namespace solver_detail;

// Rays per random stream: large enough that seeding costs nothing, small enough for both cores to share
// even the short last iterations.
constexpr long kChunk = 2048;
// Scores are a source's colour fractions (each in [0, 1]) in units of 2^-32: an element can take 2^31
// rays in one iteration before its sum overflows, and the rounding, 1e-10 of a ray, is far below the noise.
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

long localLinesDefaultRays(std::size_t elements) {
  return std::max<long>(100000, 1000 * static_cast<long>(elements));
}

SolverStatus localLines(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                        const IterationSink& sink, RgbField* standardError) {
  B = system.emission;
  const auto n = static_cast<Eigen::Index>(system.size());
  RgbField variance = RgbField::Zero(n, 3);
  if (standardError) *standardError = variance;
  const SolverStatus valid = validate(system, false);
  if (valid != SolverStatus::Success) return valid;
  if (!system.mesh || static_cast<Eigen::Index>(system.mesh->size()) != n) return SolverStatus::InvalidInput;
  const Mesh& mesh = *system.mesh;
  const Eigen::VectorXd& A = system.areas;
  const Stopwatch clock;
  const long budget =
      options.raysPerIteration > 0 ? options.raysPerIteration : localLinesDefaultRays(system.size());

  RgbField unshot = system.emission;
  const double emitted = totalEmittedPower(system);
  if (emitted <= 0.0) return SolverStatus::Success;
  const RayScene scene(mesh);
  const double eNorm = system.emission.norm();
  double absorbed = 0.0, escaped = 0.0;
  long raysSoFar = 0;
  std::vector<double> sourceCumulative(static_cast<std::size_t>(n));
  Scores scores(static_cast<std::size_t>(n));
  std::atomic<long> lost{0};

  for (int k = 1, cap = sweepCap(options); k <= cap; ++k) {
    double total = 0.0;
    Eigen::Index lastSource = -1;
    for (Eigen::Index j = 0; j < n; ++j) {
      const double power = unshot.row(j).sum() * A(j);
      if (power > 0.0) lastSource = j;
      sourceCumulative[std::size_t(j)] = total += power;
    }
    if (total <= 0.0 || lastSource < 0) return SolverStatus::Success;
    // Constant power per ray; the shrink by 1e-12 keeps the count independent of the units (see
    // stochasticJacobi).
    const long rays =
        std::max(1L, static_cast<long>(std::ceil(double(budget) * (total / emitted) * (1.0 - 1e-12))));
    scores.clear();
    lost = 0;
    const long chunks = (rays + kChunk - 1) / kChunk;
    tbb::parallel_for(tbb::blocked_range<long>(0, chunks, 1), [&](const tbb::blocked_range<long>& range) {
      long lostHere = 0;
      for (long chunk = range.begin(); chunk != range.end(); ++chunk) {
        PairRandom random(options.seed, static_cast<std::uint64_t>(k), static_cast<std::uint64_t>(chunk));
        for (long r = chunk * kChunk, end = std::min(rays, r + kChunk); r < end; ++r) {
          const std::size_t picked = sampleCumulative(sourceCumulative, random.uniform() * total);
          auto j = static_cast<Eigen::Index>(std::min(picked, std::size_t(n - 1)));
          if (!(unshot.row(j).sum() > 0.0)) j = lastSource;  // rounding at the top of the running sum
          const Source source = sourceOf(mesh, j);
          const double u = random.uniform(), v = random.uniform();
          const Vec3 origin = pointOnPolygon(source.corners, source.count, u, v);
          const double a = random.uniform(), b = random.uniform();
          const RayHit hit =
              scene.firstHit(origin, cosineDirection(source.normal, a, b), static_cast<int>(j));
          if (hit.element < 0 || !hit.frontSide) {
            ++lostHere;
            continue;
          }
          // The ray's power is total / rays, split over the channels as the source's unshot radiosity is.
          const Eigen::RowVector3d fraction = unshot.row(j) / unshot.row(j).sum();
          std::int64_t score[6];
          for (int c = 0; c < 3; ++c) {
            score[c] = std::llround(fraction(c) * kFixed);
            score[3 + c] = std::llround(fraction(c) * fraction(c) * kFixed);
          }
          scores.add(hit.element, score);
        }
      }
      lost += lostHere;
    });
    raysSoFar += rays;
    const double perRay = total / double(rays);
    escaped += double(lost.load()) * perRay;

    for (Eigen::Index j = 0; j < n; ++j) {
      const Eigen::Array3d rho = system.reflectance.row(j).array().transpose();
      Eigen::Array3d in, sumVariance;
      for (int c = 0; c < 3; ++c) {
        in(c) = double(scores.at(j, c)) / kFixed * perRay;
        const double squares = double(scores.at(j, 3 + c)) / kFixed * perRay * perRay;
        // Variance of a sum of `rays` independent scores, estimated from the same scores.
        sumVariance(c) = std::max(0.0, squares - in(c)*in(c) / double(rays));
      }
      absorbed += ((1.0 - rho) * in).sum();
      const Eigen::Array3d gain = rho * in / A(j);
      unshot.row(j) = gain.matrix().transpose();
      B.row(j) += gain.matrix().transpose();
      variance.row(j) += (rho.square() * sumVariance / (A(j) * A(j))).matrix().transpose();
    }
    IterationRecord rec;
    rec.iteration = k;
    rec.B = B;
    rec.unshot = unshot;
    rec.unshotPower = unshot.rowwise().sum().cwiseProduct(A).sum();
    rec.emittedPower = emitted;
    rec.absorbedPower = absorbed;
    rec.escapedPower = escaped;
    rec.residual = eNorm > 0 ? unshot.norm() / eNorm : unshot.norm();
    rec.standardError = relativeAreaRms(variance.cwiseSqrt(), B, A);
    rec.rays = raysSoFar;
    rec.seconds = clock.seconds();
    const bool done = rec.unshotPower <= options.tolerance * emitted;
    if (!B.allFinite()) return SolverStatus::NumericalIssue;
    if (standardError) *standardError = variance.cwiseSqrt();
    if (sink) sink(std::move(rec));
    if (done) return SolverStatus::Success;
  }
  return SolverStatus::NoConvergence;
}

}  // namespace rt
