#include "core/solvers/random_walks.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/formfactor/ray_scene.h"
#include "core/formfactor/sampling.h"

namespace rt {
namespace solver_detail {

long defaultWalks(const RadiositySystem& system, const SolverOptions& options) {
  return options.raysPerIteration > 0 ? options.raysPerIteration
                                      : std::max<long>(1000, 100 * static_cast<long>(system.size()));
}

SolverStatus walkSolve(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                       const IterationSink& sink, RgbField* standardError, WalkJumps& jumps, long batch,
                       const WalkObserver& observer) {
  B = system.emission;
  const auto n = static_cast<Eigen::Index>(system.size());
  if (standardError) *standardError = RgbField::Zero(n, 3);
  const Eigen::VectorXd& A = system.areas;
  const RgbField& rho = system.reflectance;
  const Stopwatch clock;
  Random random(options.seed);
  const bool absorption = options.walkEstimator == SolverOptions::WalkEstimator::Absorption;

  std::vector<double> sourceCumulative(static_cast<std::size_t>(n));
  double emitted = 0.0;
  for (Eigen::Index j = 0; j < n; ++j)
    sourceCumulative[std::size_t(j)] = emitted += system.emission.row(j).sum() * A(j);
  if (emitted <= 0.0) return SolverStatus::Success;
  Eigen::VectorXd survival(n);
  for (Eigen::Index j = 0; j < n; ++j) survival(j) = std::min(rho.row(j).maxCoeff(), 1.0 - 1e-12);

  // Sums over walks of each walk's total score per element (power), and of its square: walks are independent,
  // scores within one walk are not, hence the per-walk merge below.
  RgbField sum = RgbField::Zero(n, 3), sumSquares = RgbField::Zero(n, 3);
  double absorbed = 0.0, escaped = 0.0;
  long walks = 0;
  bool truncated = false;
  std::vector<std::pair<int, Eigen::RowVector3d>> scores;
  // A walk ends with probability 1, but at rho = 1 (a singular system) not in finite time. Truncating at this
  // length biases the result by at most q^kMaxSteps of the weight: below 1e-13 for every survival probability
  // q <= 0.9997.
  constexpr int kMaxSteps = 100000;

  auto score = [&scores](int k, const Eigen::RowVector3d& s) {
    for (auto& [element, value] : scores)
      if (element == k) {
        value += s;
        return;
      }
    scores.emplace_back(k, s);
  };

  for (int it = 1, cap = sweepCap(options); it <= cap; ++it) {
    for (long w = 0; w < batch; ++w) {
      scores.clear();
      const std::size_t picked = sampleCumulative(sourceCumulative, random.uniform() * emitted);
      const auto source = static_cast<Eigen::Index>(std::min(picked, std::size_t(n - 1)));
      const double sourcePower = system.emission.row(source).sum() * A(source);
      if (sourcePower <= 0.0) continue;
      Eigen::RowVector3d weight = system.emission.row(source) * A(source) * (emitted / sourcePower);
      WalkPosition at = jumps.start(static_cast<int>(source), random);
      RecordedWalk path;
      if (observer) {
        path.source = static_cast<int>(source);
        path.points.push_back(at.point);
      }
      int step = 0;
      for (; step < kMaxSteps; ++step) {
        const WalkPosition next = jumps.jump(at, random);
        const int hit = next.element;
        if (hit < 0) {
          escaped += weight.sum();
          path.escapedPower += weight.sum();
          path.end = RecordedWalk::End::Escaped;
          break;
        }
        const Eigen::RowVector3d reflected = weight.cwiseProduct(rho.row(hit));
        absorbed += weight.sum() - reflected.sum();
        if (observer) {
          path.landings.push_back(hit);
          path.points.push_back(next.point);
          path.weights.push_back(weight);
          path.absorbedPower += weight.sum() - reflected.sum();
        }
        const double q = survival(hit);
        const bool survives = q > 0.0 && random.uniform() < q;
        if (!absorption) score(hit, reflected);
        if (!survives) {
          if (absorption) score(hit, reflected / (1.0 - q));
          break;
        }
        weight = reflected / q;
        at = next;
      }
      // A walk cut off by the limit scored nothing under the absorption estimator: the estimate of a system
      // that (nearly) never absorbs is not to be trusted, whatever its standard error says.
      if (step == kMaxSteps) {
        truncated = true;
        path.end = RecordedWalk::End::Cut;
      }
      if (observer) observer(std::move(path));
      for (const auto& [element, value] : scores) {
        sum.row(element) += value;
        sumSquares.row(element) += value.cwiseProduct(value);
      }
    }
    walks += batch;
    const double W = double(walks);
    const RgbField mean = sum / W;
    const RgbField meanVariance =
        ((sumSquares.array() / W - mean.array().square()).cwiseMax(0.0) / W).matrix();
    B = system.emission + (A.cwiseInverse().asDiagonal() * mean);
    RgbField se = (A.cwiseInverse().asDiagonal() * meanVariance.cwiseSqrt());
    IterationRecord rec;
    rec.iteration = it;
    rec.B = B;
    rec.emittedPower = emitted;
    rec.absorbedPower = absorbed / W;
    rec.escapedPower = escaped / W;
    rec.standardError = relativeAreaRms(se, B, A);
    // Without F (continuous walks) there is no residual to compute: the stopping measure stands in for it.
    rec.residual = system.F ? system.relativeResidual(B) : rec.standardError;
    rec.rays = walks;
    rec.seconds = clock.seconds();
    const bool done = !truncated && rec.standardError <= options.tolerance;
    if (standardError) *standardError = se;
    if (sink) sink(std::move(rec));
    if (done) return SolverStatus::Success;
  }
  return SolverStatus::NoConvergence;
}

}  // namespace solver_detail

namespace {

using namespace solver_detail;

// Continuous walks: photon trajectories traced through the mesh. The first line leaves a uniform point of the
// source; every later one leaves the point the walk arrived at; each in a cosine-distributed direction.
class TracedJumps : public WalkJumps {
 public:
  explicit TracedJumps(const Mesh& mesh) : mesh_(mesh), scene_(mesh), lift_(1e-9 * scene_.sceneSize()) {}
  WalkPosition start(int source, Random& random) override {
    const Polygon polygon = mesh_.polygon(source);
    const double u = random.uniform(), v = random.uniform();
    return {source, pointOnPolygon(polygon, u, v)};
  }
  WalkPosition jump(const WalkPosition& from, Random& random) override {
    const Vec3 normal = mesh_.elements[static_cast<std::size_t>(from.element)].normal.normalized();
    // Off the element's plane by far less than any feature, so that the line cannot start behind it.
    const Vec3 origin = from.point + lift_ * normal;
    const double a = random.uniform(), b = random.uniform();
    const Vec3 direction = cosineDirection(normal, a, b);
    const RayHit hit = scene_.firstHit(origin, direction, from.element);
    if (hit.element < 0 || !hit.frontSide) return {};
    return {hit.element, origin + hit.distance * direction};
  }

 private:
  const Mesh& mesh_;
  const RayScene scene_;
  const double lift_;
};

}  // namespace

SolverStatus recordWalks(const std::string& solver, const RadiositySystem& system,
                         const SolverOptions& options, long count, std::vector<RecordedWalk>& walks) {
  walks.clear();
  const bool continuous = solver == "photon-density";
  if ((!continuous && solver != "random-walk" && solver != "random-walk-absorption") || count < 1)
    return SolverStatus::InvalidInput;
  const SolverStatus valid = solver_detail::validate(system, !continuous);
  if (valid != SolverStatus::Success) return valid;
  const Mesh* mesh = system.mesh;
  if (continuous && (!mesh || mesh->size() != system.size())) return SolverStatus::InvalidInput;
  // One batch of `count` walks: the random numbers run through the walks in order, so these are the first
  // `count` walks of the solver's own first batch, however large that is.
  SolverOptions one = options;
  one.maxIterations = 1;
  one.walkEstimator = solver == "random-walk-absorption" ? SolverOptions::WalkEstimator::Absorption
                                                         : SolverOptions::WalkEstimator::Collision;
  const bool centroids = !continuous && mesh && mesh->size() == system.size();
  const WalkObserver keep = [&](RecordedWalk&& walk) {
    if (centroids) {
      walk.points.front() = mesh->elements[static_cast<std::size_t>(walk.source)].centroid;
      for (std::size_t k = 0; k < walk.landings.size(); ++k)
        walk.points[k + 1] = mesh->elements[static_cast<std::size_t>(walk.landings[k])].centroid;
    }
    walks.push_back(std::move(walk));
  };
  RgbField B;
  std::unique_ptr<WalkJumps> jumps;
  if (continuous)
    jumps = std::make_unique<TracedJumps>(*mesh);
  else
    jumps = solver_detail::rowJumps(*system.F);
  const SolverStatus status = solver_detail::walkSolve(system, B, one, {}, nullptr, *jumps, count, keep);
  return status == SolverStatus::NoConvergence ? SolverStatus::Success : status;
}

SolverStatus photonDensity(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                           const IterationSink& sink, RgbField* standardError) {
  B = system.emission;
  if (standardError) *standardError = RgbField::Zero(static_cast<Eigen::Index>(system.size()), 3);
  const SolverStatus valid = solver_detail::validate(system, false);
  if (valid != SolverStatus::Success) return valid;
  if (!system.mesh || system.mesh->size() != system.size()) return SolverStatus::InvalidInput;
  SolverOptions collision = options;
  collision.walkEstimator = SolverOptions::WalkEstimator::Collision;
  TracedJumps jumps(*system.mesh);
  return solver_detail::walkSolve(system, B, collision, sink, standardError, jumps,
                                  solver_detail::defaultWalks(system, options));
}

}  // namespace rt
