#include "core/refine/transfer.h"

#include <algorithm>
#include <cmath>

#include "core/formfactor/analytic.h"
#include "core/polygon.h"

namespace rt {
namespace {

Eigen::AlignedBox3d boundsOf(const Polygon& p) {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : p) box.extend(v);
  return box;
}

// True when some vertex of p lies strictly in front of the plane (origin, normal).
bool reachesInFront(const Polygon& p, const Vec3& origin, const Vec3& normal, double eps) {
  for (const Vec3& v : p)
    if ((v - origin).dot(normal) > eps) return true;
  return false;
}

}  // namespace

std::vector<SurfaceSample> stratifiedSamples(const Polygon& P, int perSide) {
  std::vector<SurfaceSample> samples;
  if (P.size() < 3) return samples;
  if (perSide <= 1 && P.size() <= 4) {
    samples.push_back({polygonCentroid(P), 1.0});
    return samples;
  }
  const int m = std::max(1, perSide);
  const double total = polygonArea(P);
  if (!(total > 0)) return samples;
  for (const Polygon& t : fanTriangulate(P)) {
    const double w = polygonArea(t) / (total * m * m);
    if (w <= 0) continue;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        const double su = std::sqrt((i + 0.5) / m), v = (j + 0.5) / m;
        samples.push_back({(1 - su) * t[0] + su * (1 - v) * t[1] + su * v * t[2], w});
      }
  }
  return samples;
}

VisibilityOracle::VisibilityOracle(const Scene& scene) : patches_(static_cast<int>(scene.patches.size())) {
  const Eigen::AlignedBox3d all = scene.bounds();
  const double eps = 1e-9 * (all.isEmpty() ? 1.0 : all.diagonal().norm());
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const Patch& p : scene.patches) {
    const Vec3 normal = newellNormal(p.vertices).normalized();
    blockers_.push_back({p.vertices, normal, normal.dot(p.vertices[0])});
    Eigen::AlignedBox3d box = boundsOf(p.vertices);
    box.min().array() -= eps;
    box.max().array() += eps;
    boxes.push_back(box);
  }
  candidates_.assign(static_cast<std::size_t>(patches_) * patches_, {});
  for (int a = 0; a < patches_; ++a)
    for (int b = 0; b < patches_; ++b) {
      if (a == b) continue;
      const Eigen::AlignedBox3d pair = boxes[a].merged(boxes[b]);
      const Patch& pa = scene.patches[a];
      const Patch& pb = scene.patches[b];
      for (int o = 0; o < patches_; ++o) {
        if (o == a || o == b || !pair.intersects(boxes[o])) continue;
        const Polygon& ov = scene.patches[o].vertices;
        if (reachesInFront(ov, pa.vertices[0], blockers_[a].normal, eps) &&
            reachesInFront(ov, pb.vertices[0], blockers_[b].normal, eps))
          candidates_[a * patches_ + b].push_back(o);
      }
    }
}

bool VisibilityOracle::crosses(const Blocker& blocker, const Vec3& a, const Vec3& d) const {
  const double denom = blocker.normal.dot(d);
  if (std::abs(denom) < 1e-14 * d.norm()) return false;
  const double t = (blocker.offset - blocker.normal.dot(a)) / denom;
  if (t <= 1e-7 || t >= 1 - 1e-7) return false;
  const Vec3 p = a + t * d;
  const std::size_t n = blocker.vertices.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& e0 = blocker.vertices[k];
    const Vec3& e1 = blocker.vertices[(k + 1) % n];
    if ((e1 - e0).cross(p - e0).dot(blocker.normal) < 0) return false;
  }
  return true;
}

bool VisibilityOracle::segmentClear(const Vec3& a, const Vec3& b, int patchA, int patchB) const {
  const Vec3 d = b - a;
  for (int o : candidates(patchA, patchB))
    if (crosses(blockers_[o], a, d)) return false;
  return true;
}

double VisibilityOracle::visibleFraction(const Vec3& x, const std::vector<SurfaceSample>& targets,
                                         int patchFrom, int patchTo) const {
  const std::vector<int>& blockers = candidates(patchFrom, patchTo);
  if (blockers.empty() || targets.empty()) return 1.0;
  rays_.fetch_add(targets.size(), std::memory_order_relaxed);
  double visible = 0;
  for (const SurfaceSample& s : targets) {
    const Vec3 d = s.point - x;
    bool clear = true;
    for (int o : blockers)
      if (crosses(blockers_[o], x, d)) {
        clear = false;
        break;
      }
    if (clear) visible += s.weight;
  }
  return visible;
}

std::pair<double, double> pieceFormFactors(const SurfacePiece& a, const SurfacePiece& b,
                                           const VisibilityOracle& visibility,
                                           const TransferOptions& options) {
  if (a.patch == b.patch || a.area <= 0 || b.area <= 0) return {0.0, 0.0};
  const bool aSmaller = a.area <= b.area;
  const SurfacePiece& small = aSmaller ? a : b;
  const SurfacePiece& large = aSmaller ? b : a;
  const double distance = (small.centroid - large.centroid).norm();
  const bool near = distance < options.nearFactor * (std::sqrt(small.area) + std::sqrt(large.area));
  const std::vector<SurfaceSample> receivers = stratifiedSamples(*small.polygon, near ? 3 : 1);
  std::vector<SurfaceSample> targets;
  if (visibility.mayBeOccluded(small.patch, large.patch)) {
    const int triangles = static_cast<int>(large.polygon->size()) - 2;
    const int perSide =
        std::max(1, static_cast<int>(std::lround(std::sqrt(options.visibilitySamples / double(triangles)))));
    targets = stratifiedSamples(*large.polygon, perSide);
  }
  double fSmallLarge = 0;
  for (const SurfaceSample& r : receivers) {
    const double unoccluded = pointToPolygonFormFactor(r.point, small.normal, *large.polygon);
    if (unoccluded <= 0) continue;
    fSmallLarge +=
        r.weight * unoccluded * visibility.visibleFraction(r.point, targets, small.patch, large.patch);
  }
  const double fLargeSmall = fSmallLarge * small.area / large.area;
  return aSmaller ? std::make_pair(fSmallLarge, fLargeSmall) : std::make_pair(fLargeSmall, fSmallLarge);
}

std::pair<double, double> pieceFormFactorEstimate(const SurfacePiece& a, const SurfacePiece& b) {
  if (a.patch == b.patch) return {0.0, 0.0};
  return {pointToPolygonFormFactor(a.centroid, a.normal, *b.polygon),
          pointToPolygonFormFactor(b.centroid, b.normal, *a.polygon)};
}

}  // namespace rt
