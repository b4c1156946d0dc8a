// Element-to-element form factors: F_ij = (1/A_i) integral over i of F(dA at x -> visible part of j), by
// adaptive cubature. Also the lesson-facing views of the same computation: the visible region from a point,
// the cubature points.
#include <algorithm>
#include <cmath>

#include "core/formfactor/analytic.h"
#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/polygon.h"
#include "exact/adaptive_cubature.h"
#include "exact/exact_kernel.h"
#include "exact/exact_reference.h"
#include "exact/point_evaluator.h"
#include "exact/shaft.h"
#include "exact/visibility_events.h"

namespace rt::exact {
namespace {

// `base` is the part of A_i F_ij known without cubature (the analytic unoccluded value when the cubature
// integrates only what the occluders take away): relative targets refer to the entry, base minus the
// integral.
CubatureSettings settingsFor(const ExactOptions& options, bool occluded, double sourceArea, double base) {
  CubatureSettings settings;
  settings.order = occluded ? options.occludedRuleOrder : options.ruleOrder;
  settings.maxEvaluations = options.maxEvaluations;
  // Without the event split, occluded integrands have kinks anywhere: split once before adapting so that a
  // shadow smaller than the element cannot slip between identical coarse and refined estimates.
  settings.initialSplits = occluded && !options.splitAlongEvents ? 1 : 0;
  const double relative = occluded ? options.occludedTolerance : options.tolerance;
  // The cubature integrates A_i F(x): the floor, a form factor, scales with the source's area (so that a
  // scene in millimetres and the same scene in metres get the same targets).
  const double floor = options.absoluteFloor * sourceArea;
  settings.tolerance = [relative, floor, base](double estimate) {
    return relative * std::max(std::abs(base - estimate), floor);
  };
  return settings;
}

// Elements whose bounding spheres overlap (neighbours sharing an edge or a corner, or close): there F(x) is
// nearly singular along the common boundary, where the direct cubature's error estimate is too optimistic.
bool near(const PairGeometry& pair) {
  auto sphere = [](const Polygon& p, Vec3& centre, double& radius) {
    centre = Vec3::Zero();
    for (const Vec3& v : p) centre += v;
    centre /= static_cast<double>(p.size());
    radius = 0;
    for (const Vec3& v : p) radius = std::max(radius, (v - centre).norm());
  };
  Vec3 ci, cj;
  double ri, rj;
  sphere(pair.sourcePolygon, ci, ri);
  sphere(pair.receiverPolygon, cj, rj);
  return (ci - cj).norm() < ri + rj;
}

// True when one occluder, a convex polygon, cuts every segment from the integration domain to the receiver
// with a margin (polygonCutsEverySegment, the quadrature method's proof): then nothing of the receiver is
// seen from anywhere on the source and F_ij = 0 exactly. (The cubature would find the same zero, after
// splitting the source along every visibility event.)
bool whollyHidden(const PairGeometry& pair) {
  const double eps = 100 * kGeometricEpsilon * pair.scale;
  for (const Polygon& o : pair.blockers) {
    const Vec3 normal = newellNormal(o);
    const double length = normal.norm();
    if (o.size() < 3 || !(length > 0)) continue;
    const Vec3 n = normal / length;
    bool convex = true;
    for (std::size_t k = 0; k < o.size() && convex; ++k)
      convex =
          (o[(k + 1) % o.size()] - o[k]).cross(o[(k + 2) % o.size()] - o[(k + 1) % o.size()]).dot(n) >= 0;
    if (!convex) continue;
    if (polygonCutsEverySegment(pair.integrationDomain.data(),
                                static_cast<int>(pair.integrationDomain.size()), pair.receiverPolygon.data(),
                                static_cast<int>(pair.receiverPolygon.size()), o.data(),
                                static_cast<int>(o.size()), n, n.dot(o[0]), eps))
      return true;
  }
  return false;
}

EntryResult integratePair(const Mesh& mesh, const PairGeometry& pair, const ExactOptions& options,
                          std::vector<CubaturePoint>* points) {
  EntryResult entry;
  entry.facing = pair.facing;
  entry.occluded = !pair.occluders.empty();
  if (!pair.facing) return entry;
  const double area = mesh.elements[pair.source].area;
  // The unoccluded entry is the analytic value (exact up to rounding, even for elements sharing an edge,
  // where F(x) is singular and cubature error estimates are too optimistic). For occluded neighbours, the
  // cubature integrates only what the occluders take away, F_unoccluded(x) - F_visible(x): zero wherever
  // nothing is in the way, so the singular neighbourhood of the common edge usually costs nothing. Occluded
  // pairs further apart integrate F_visible(x) directly (smooth away from shadow boundaries, and cheaper).
  // Lessons asking for the cubature points get the direct integral, whose points show F itself.
  const bool subtract = options.analyticUnoccluded && points == nullptr && (!entry.occluded || near(pair));
  const double unoccluded =
      subtract ? rt::polygonToPolygonFormFactor(pair.sourcePolygon, pair.receiverPolygon) : 0.0;
  if (subtract && !entry.occluded) {
    entry.value = unoccluded;
    entry.analytic = true;
    return entry;
  }
  // Lessons asking for the cubature points get them even where the answer is known.
  if (entry.occluded && points == nullptr && whollyHidden(pair)) return entry;  // value 0, estimate 0
  const PointEvaluator evaluate(pair, options.booleans);
  const AdaptiveCubature cubature(settingsFor(options, entry.occluded, area, unoccluded * area));
  std::vector<WeightedPoint> finalPoints;
  bool anyVisible = false;  // all points in full shadow: F_ij = 0 exactly, not a difference of two integrals
  long unmetered = 0;
  const auto f = [&](const Vec3& x) {
    if (options.meter && ++unmetered == kMeterBatch) {
      options.meter(unmetered);
      unmetered = 0;
    }
    const double visible = evaluate(x);
    anyVisible = anyVisible || visible > 0;
    return subtract ? evaluate.unoccluded(x) - visible : visible;
  };
  std::vector<Polygon> cells{pair.integrationDomain};
  if (entry.occluded && options.splitAlongEvents) {
    cells = splitAlongEvents(pair.integrationDomain, pair.sourceNormal, visibilityEvents(pair),
                             kGeometricEpsilon * pair.scale * 100);
    entry.eventCells = static_cast<long>(cells.size());
  }
  const CubatureResult result = cubature.integrateCells(cells, f, points ? &finalPoints : nullptr);
  if (options.meter && unmetered > 0) options.meter(unmetered);
  entry.value = subtract ? std::max(0.0, unoccluded - result.value / area) : result.value / area;
  entry.errorEstimate = result.errorEstimate / area;
  if (!anyVisible) entry.value = entry.errorEstimate = 0;  // the direct integral over the same points
  entry.evaluations = result.evaluations;
  entry.exactEvaluations = evaluate.exactEvaluations();
  entry.splitEvaluations = evaluate.splitEvaluations();
  entry.converged = result.converged;
  if (points)
    for (const WeightedPoint& p : finalPoints)
      points->push_back({p.position, p.weight, evaluate(p.position)});
  return entry;
}

}  // namespace

ExactOptions exactOptionsFor(double tolerance) {
  ExactOptions options;
  if (tolerance > 0 && std::isfinite(tolerance)) {
    options.tolerance = tolerance;
    options.occludedTolerance = std::max(tolerance, 1e-7);
  }
  options.booleans = Booleans::Split;
  return options;
}

EntryResult elementFormFactor(const Mesh& mesh, int source, int receiver, const ExactOptions& options,
                              std::vector<CubaturePoint>* points, const ElementIndex* index) {
  if (source == receiver)
    return EntryResult{0, 0, false, false, 0, 0, 0, true};  // planar elements do not see themselves
  return integratePair(mesh, setUpPair(mesh, source, receiver, true, index), options, points);
}

double pointFormFactor(const Mesh& mesh, int source, const Vec3& x, int receiver, Booleans booleans) {
  if (source == receiver) return 0;
  const PairGeometry pair = setUpPair(mesh, source, receiver);
  if (!pair.facing) return 0;
  return PointEvaluator(pair, booleans)(x);
}

std::vector<CubaturePoint> cubaturePoints(const Mesh& mesh, int source, int receiver,
                                          const ExactOptions& options) {
  std::vector<CubaturePoint> points;
  elementFormFactor(mesh, source, receiver, options, &points);
  return points;
}

VisibleRegion visibleRegion(const Mesh& mesh, int source, const Vec3& point, int receiver) {
  VisibleRegion region;
  region.source = source;
  region.receiver = receiver;
  region.point = point;
  if (source == receiver) return region;
  const PairGeometry pair = setUpPair(mesh, source, receiver);
  region.occluders = pair.occluders;
  const detail::ExactVisibility visibility = detail::exactVisibility(
      point, pair.sourceNormal, pair.receiverPolygon, pair.receiverNormal, pair.occluderPolygons);
  region.facing = visibility.projection.receiverFacesPoint;
  region.clippedReceiver = visibility.projection.clippedReceiver;
  region.occluderProjections = visibility.projection.projections;
  for (int owner : visibility.projection.projectionOwners)
    region.projectionOwners.push_back(pair.occluders[owner]);
  region.visible = visibility.visible;
  region.formFactor = pointToRegionFormFactor(point, pair.sourceNormal, region.visible);
  region.unoccludedFormFactor = pointToPolygonFormFactor(point, pair.sourceNormal, region.clippedReceiver);
  return region;
}

Eigen::MatrixXd errorMap(const FormFactorMatrix& method, const FormFactorMatrix& exact) {
  if (method.rows() != exact.rows() || method.cols() != exact.cols())
    throw std::invalid_argument("errorMap: matrices of different sizes (" + std::to_string(method.rows()) +
                                " vs " + std::to_string(exact.rows()) + " rows)");
  return (method - exact).cwiseAbs();
}

}  // namespace rt::exact
