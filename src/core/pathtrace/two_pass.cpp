#include "core/pathtrace/two_pass.h"

#include <algorithm>
#include <cmath>

#include "core/formfactor/analytic.h"
#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/sampling.h"
#include "core/geometry/plane_clip.h"
#include "core/parallel.h"
#include "core/pathtrace/path_tracer.h"

namespace rt {
namespace {

// The fraction of each element that receives light at all: of 16 stratified points, those from which a ray
// along the normal does not meet the back of a polygon (the inside of a block standing on the element). The
// element's B is an average that counts the rest as dark, and a gather ray can only reach the part that is
// not: there the radiosity is B / fraction. At least 1/16.
std::vector<double> receivingFractions(const Mesh& mesh, const RayScene& rays) {
  std::vector<double> fractions(mesh.size(), 1.0);
  constexpr int kPoints = 16;
  const StrataGrid grid(kPoints);
  parallelFor(std::size_t(0), mesh.size(), [&](std::size_t e) {
    const Polygon polygon = mesh.polygon(static_cast<int>(e));
    const PolygonSampler sampler(polygon.data(), static_cast<int>(polygon.size()));
    const Vec3& normal = mesh.elements[e].normal;
    PairRandom random(0x5eed, e, 0);
    int receiving = 0;
    for (int k = 0; k < kPoints; ++k) {
      const Vec2 uv = grid.sample(k, random);
      const RayHit hit = rays.firstHit(sampler.point(uv.x(), uv.y()), normal, static_cast<int>(e));
      receiving += hit.element < 0 || hit.frontSide;
    }
    fractions[e] = std::max(receiving, 1) / static_cast<double>(kPoints);
  });
  return fractions;
}

}  // namespace

TwoPass::TwoPass(const TracingScene& tracing, const Mesh& solution, const RgbField& B,
                 const FormFactorMatrix* F)
    : tracing_(tracing),
      solution_(solution),
      B_(B),
      shaft_(tracing.mesh()),
      solutionRays_(std::make_unique<RayScene>(solution)),
      patchElement_(tracing.scene().patches.size(), -1),
      patchPolygons_(tracing.scene().patches.size()) {
  for (std::size_t e = 0; e < tracing.mesh().size(); ++e)
    patchPolygons_[static_cast<std::size_t>(tracing.patchOf(static_cast<int>(e)))].push_back(
        tracing.mesh().polygon(static_cast<int>(e)));
  for (std::size_t e = solution.size(); e-- > 0;)
    patchElement_[static_cast<std::size_t>(solution.elements[e].patch)] = static_cast<int>(e);
  receiving_ = receivingFractions(solution, *solutionRays_);
  if (!F || F->rows() != static_cast<Eigen::Index>(solution.size())) return;
  std::vector<Eigen::Index> emitters;
  for (Eigen::Index l = 0; l < F->rows(); ++l)
    if ((solution.emission.row(l).array() > 0).any()) emitters.push_back(l);
  indirect_ = RgbField::Zero(F->rows(), 3);
  for (Eigen::Index i = 0; i < F->rows(); ++i) {
    Rgb direct = Rgb::Zero();
    for (Eigen::Index l : emitters) direct += (*F)(i, l) * solution.emission.row(l).transpose().array();
    for (int c = 0; c < 3; ++c) {
      const double rho = solution.reflectance(i, c);
      if (rho > 0) indirect_(i, c) = (B(i, c) - solution.emission(i, c)) / rho - direct(c);
    }
  }
}

Rgb TwoPass::directSample(const Vec3& point, const Vec3& normal, int element, const Vec2& light) const {
  Rgb H = Rgb::Zero();
  const int patch = element >= 0 ? tracing_.patchOf(element) : -1;
  for (const Emitter& emitter : tracing_.emitters()) {
    if (emitter.element == element) continue;
    const double unoccluded = pointToPolygonFormFactor(point, normal, emitter.polygon);
    if (unoccluded <= 0) continue;
    double hidden = 0;
    if (shaft_.mayBeOccluded(point, normal, patch, emitter.element)) {
      const Vec3 y = pointOnPolygon(emitter.polygon, light.x(), light.y());
      const double kernel = pointToPointKernel(point, normal, y, emitter.normal);
      if (kernel > 0 && !tracing_.rays().visible(point, y, element, emitter.element))
        hidden = kernel * emitter.area;
    }
    H += emitter.emission * (unoccluded - hidden);
  }
  return H;
}

double TwoPass::hiddenExactly(const Vec3& point, const Vec3& normal, int emitter,
                              const std::vector<int>& blockers) const {
  const Polygon light = tracing_.mesh().polygon(emitter);
  const Vec3& lightNormal = tracing_.mesh().elements[static_cast<std::size_t>(emitter)].normal;
  const double size = (light[0] - point).norm();
  // The light's part above the point's horizon; the point itself is the clipper's one-vertex "source".
  ConvexPolygon source, receiver;
  source.v[0] = point;
  source.count = 1;
  clipToFront(light.data(), static_cast<int>(light.size()), point, normal, 1e-12 * size, receiver);
  if (receiver.count < 3) return 0;
  std::vector<OccluderPolygon> occluders;
  for (int k : blockers)
    for (const Polygon& polygon : patchPolygons_[static_cast<std::size_t>(k)])
      occluders.push_back({&polygon, -1});
  static const std::vector<SolidPlanes> kNoSolids;
  const ShadowClipper clipper(source, normal, receiver, lightNormal, occluders, kNoSolids);
  return clipper.occluders().empty() ? 0 : clipper.hidden(point, clipper.occluders());
}

Rgb TwoPass::direct(const SurfacePoint& point, int element, const TwoPassOptions& options,
                    std::uint64_t index, Rgb& error) const {
  Rgb H = Rgb::Zero();
  error = Rgb::Zero();
  const int patch = element >= 0 ? tracing_.patchOf(element) : -1;
  const int batches = std::clamp(options.batches, 1, std::max(1, options.shadowRays));
  const int perBatch = std::max(1, options.shadowRays / batches);
  const StrataGrid grid(perBatch);
  const auto& emitters = tracing_.emitters();
  for (std::size_t l = 0; l < emitters.size(); ++l) {
    const Emitter& emitter = emitters[l];
    if (emitter.element == element) continue;
    const double unoccluded = pointToPolygonFormFactor(point.position, point.normal, emitter.polygon);
    if (unoccluded <= 0) continue;
    if (element >= 0) {
      std::vector<int> blockers;
      shaft_.candidates(point.position, point.normal, patch, emitter.element, blockers);
      const double hidden =
          blockers.empty() ? 0 : hiddenExactly(point.position, point.normal, emitter.element, blockers);
      H += emitter.emission * std::max(0.0, unoccluded - hidden);
      continue;
    }
    if (!shaft_.mayBeOccluded(point.position, point.normal, patch, emitter.element)) {
      H += emitter.emission * unoccluded;
      continue;
    }
    // Lambert's form factor less what is hidden: the hidden part's estimate is zero where every ray gets
    // through, so its error vanishes away from shadows instead of being that of the whole integral.
    const PolygonSampler sampler(emitter.polygon.data(), static_cast<int>(emitter.polygon.size()));
    RgbMean hidden;
    for (int b = 0; b < batches; ++b) {
      PairRandom random(options.seed, index, (l << 8) + static_cast<std::uint64_t>(b));
      double sum = 0;
      for (int k = 0; k < perBatch; ++k) {
        const Vec2 uv = grid.sample(k, random);
        const Vec3 y = sampler.point(uv.x(), uv.y());
        const double kernel = pointToPointKernel(point.position, point.normal, y, emitter.normal);
        if (kernel > 0 && !tracing_.rays().visible(point.position, y, element, emitter.element))
          sum += kernel;
      }
      hidden.add(Rgb::Constant(sum * emitter.area / perBatch));
    }
    H += emitter.emission * (unoccluded - hidden.mean()(0));
    error += (emitter.emission * hidden.standardError()(0)).square();
  }
  error = error.sqrt();
  return H;
}

Rgb TwoPass::gather(const SurfacePoint& point, int element, const TwoPassOptions& options,
                    std::uint64_t index, Rgb& error, Rgb* bounce, Rgb* bounceError,
                    double* harmonicDistance) const {
  const int ignore = element >= 0 ? patchElement_[static_cast<std::size_t>(tracing_.patchOf(element))] : -1;
  // A point on no known surface starts a hair above its plane, so that its own surface cannot catch its rays.
  const Vec3 origin =
      ignore >= 0 ? point.position : Vec3(point.position + 1e-6 * solutionRays_->sceneSize() * point.normal);
  const int batches = std::clamp(options.batches, 1, std::max(1, options.gatherRays));
  const int perBatch = std::max(1, options.gatherRays / batches);
  const StrataGrid grid(perBatch);
  // The hit's light sample and each secondary ray's direction and light sample are stratified over the batch
  // too (padding), up to kPaddedRays secondary rays; they are most of the noise left at a few rays per hit.
  constexpr int kPaddedRays = 8;
  const int padded = 1 + 2 * std::min(options.nearRays, kPaddedRays);
  RgbMean mean, firstBounce;
  double inverseDistances = 0;
  for (int b = 0; b < batches; ++b) {
    PairRandom random(options.seed, index, 0xffffff00u + static_cast<std::uint64_t>(b));
    const PaddedStrata strata(perBatch, padded, random);
    Rgb sum = Rgb::Zero(), bounceSum = Rgb::Zero();
    for (int k = 0; k < perBatch; ++k) {
      const Vec2 uv = grid.sample(k, random);
      const Vec3 direction = cosineDirection(point.normal, uv.x(), uv.y());
      const RayHit hit = solutionRays_->firstHit(origin, direction, ignore);
      if (hit.element >= 0 && hit.distance > 0) inverseDistances += 1 / hit.distance;
      if (hit.element < 0 || !hit.frontSide) continue;
      // What leaves the hit element besides its own emission: the emission is the direct part, done above.
      const auto row = static_cast<Eigen::Index>(hit.element);
      if (indirect_.rows() == 0) {
        sum += (B_.row(row) - solution_.emission.row(row)).transpose().array();
        continue;
      }
      const Element& hitElement = solution_.elements[static_cast<std::size_t>(hit.element)];
      const Vec3 y = origin + hit.distance * direction;
      const Rgb direct = directSample(y, hitElement.normal, tracing_.elementOf(hitElement.patch),
                                      strata.sample(0, k, random));
      // A hit closer than a few element sizes sees the element's flat indirect light at a large solid angle,
      // where it is worst (a block's lowest elements seen from the floor beside it): gather that part anew at
      // the hit point, from the solution one bounce further on.
      const bool near = hit.distance < options.nearFactor * std::sqrt(hitElement.area);
      const Rgb indirect =
          near ? secondaryGather(y, hitElement.normal, hit.element, options.nearRays, strata, k, random)
               : Rgb(indirect_.row(row).transpose().array());
      const Rgb rho = solution_.reflectance.row(row).transpose().array();
      sum += rho * (direct + indirect);
      bounceSum += rho * direct;
    }
    mean.add(sum / perBatch);
    firstBounce.add(bounceSum / perBatch);
  }
  error = mean.standardError();
  if (harmonicDistance)
    *harmonicDistance = inverseDistances > 0 ? batches * perBatch / inverseDistances
                                             : std::numeric_limits<double>::infinity();
  if (bounce) *bounce = firstBounce.mean();
  if (bounceError) *bounceError = firstBounce.standardError();
  return mean.mean();
}

Rgb TwoPass::secondaryGather(const Vec3& point, const Vec3& normal, int element, int rays,
                             const PaddedStrata& strata, int path, PairRandom& random) const {
  Rgb sum = Rgb::Zero();
  for (int k = 0; k < rays; ++k) {
    const Vec2 uv = strata.sample(1 + 2 * k, path, random);
    const Vec3 direction = cosineDirection(normal, uv.x(), uv.y());
    const RayHit hit = solutionRays_->firstHit(point, direction, element);
    if (hit.element < 0 || !hit.frontSide) continue;
    const auto row = static_cast<Eigen::Index>(hit.element);
    const double receiving = receiving_[static_cast<std::size_t>(hit.element)];
    if (indirect_.rows() == 0) {
      sum += (B_.row(row) - solution_.emission.row(row)).transpose().array() / receiving;
      continue;
    }
    const Element& hitElement = solution_.elements[static_cast<std::size_t>(hit.element)];
    const Vec3 y = point + hit.distance * direction;
    const Rgb direct = directSample(y, hitElement.normal, tracing_.elementOf(hitElement.patch),
                                    strata.sample(2 + 2 * k, path, random));
    sum += solution_.reflectance.row(row).transpose().array() *
           (direct + Rgb(indirect_.row(row).transpose().array()) / receiving);
  }
  return sum / std::max(1, rays);
}

std::vector<PointEstimate> TwoPass::estimate(const std::vector<SurfacePoint>& points,
                                             const TwoPassOptions& options) const {
  std::vector<int> elements(points.size());
  parallelFor(std::size_t(0), points.size(), [&](std::size_t p) {
    elements[p] = tracing_.locate({points[p].position, points[p].normal.normalized()});
  });
  return estimate(points, elements, options);
}

std::vector<PointEstimate> TwoPass::estimate(const std::vector<SurfacePoint>& points,
                                             const std::vector<int>& elements,
                                             const TwoPassOptions& options) const {
  std::vector<PointEstimate> out(points.size());
  parallelForChunks(0, points.size(), {}, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t p = lo; p != hi; ++p) {
      const SurfacePoint point{points[p].position, points[p].normal.normalized()};
      const int element = elements[p];
      PointEstimate& e = out[p];
      Rgb gatherError;
      e.HDirect = direct(point, element, options, p, e.HDirectError);
      e.H = e.HDirect + gather(point, element, options, p, gatherError, &e.HBounce, &e.HBounceError);
      e.HError = (e.HDirectError.square() + gatherError.square()).sqrt();
      e.element = element;
      if (element >= 0) {
        const Rgb rho = tracing_.mesh().reflectance.row(element).transpose().array();
        e.B = tracing_.mesh().emission.row(element).transpose().array() + rho * e.H;
        e.BError = rho * e.HError;
      }
    }
  });
  return out;
}

}  // namespace rt
