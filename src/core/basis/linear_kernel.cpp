#include "core/basis/linear_kernel.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "core/formfactor/analytic.h"
#include "core/formfactor/gauss_legendre.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/visibility.h"

namespace rt {
namespace {

// The largest distance from an element's centroid to its corners.
double radiusOf(const Mesh& mesh, int element) {
  const Element& e = mesh.elements[static_cast<std::size_t>(element)];
  double r = 0;
  for (const int v : e.vertices)
    r = std::max(r, (mesh.vertices[static_cast<std::size_t>(v)] - e.centroid).norm());
  return r;
}

// The kernel's mass on each shape function by the q-point Gauss rule a side, as fractions of the rule's
// unoccluded total (so that the caller scales them to Lambert's exact total).
void gaussShares(const Vec3& x, const Vec3& n, const ElementMap& map, const Vec3& normal, int q,
                 const std::function<bool(const Vec3&)>& visible, double* shares, std::size_t& rays) {
  const QuadratureRule& rule = gaussLegendre(q);
  double total = 0;
  double sum[4] = {0, 0, 0, 0};
  for (int a = 0; a < q; ++a)
    for (int b = 0; b < q; ++b) {
      const double u = rule.nodes[static_cast<std::size_t>(a)], v = rule.nodes[static_cast<std::size_t>(b)];
      const Vec3 y = map.point(u, v);
      const double k = pointToPointKernel(x, n, y, normal) * map.jacobian(u, v) *
                       rule.weights[static_cast<std::size_t>(a)] * rule.weights[static_cast<std::size_t>(b)];
      if (k <= 0) continue;
      total += k;
      if (visible) {
        ++rays;
        if (!visible(y)) continue;
      }
      double phi[4];
      map.shape(u, v, phi);
      for (int c = 0; c < map.count; ++c) sum[c] += k * phi[c];
    }
  for (int c = 0; c < map.count; ++c) shares[c] = total > 0 ? sum[c] / total : 0.0;
  if (total <= 0) {
    // The rule saw none of the element (a sliver at grazing): split evenly, still visible or not.
    const bool seen = !visible || (++rays, visible(map.point(0.5, 0.5)));
    for (int c = 0; c < map.count; ++c) shares[c] = seen ? 1.0 / map.count : 0.0;
  }
}

}  // namespace

WeightedFormFactor weightedPointFormFactor(const Vec3& point, const Vec3& normal, const Mesh& mesh,
                                           int element, double tolerance,
                                           const std::function<bool(const Vec3&)>& visible) {
  WeightedFormFactor out;
  const ElementMap map(mesh, element);
  const Element& f = mesh.elements[static_cast<std::size_t>(element)];
  out.count = map.count;
  out.total = pointToPolygonFormFactor(point, normal, map.p, map.count);
  if (out.total <= 0) return out;
  const double ratio = (point - f.centroid).norm() / std::max(radiusOf(mesh, element), 1e-300);
  // A far element sees a kernel that is nearly linear over it: few points split it to well under the
  // tolerance. Near the element the kernel peaks; the order doubles until the shares settle.
  int q = ratio > 6 ? 2 : ratio > 3 ? 4 : 8;
  double shares[4] = {0, 0, 0, 0};
  gaussShares(point, normal, map, f.normal, q, visible, shares, out.rays);
  if (ratio <= 1.5) {
    // Rays make the doubling dear; a shadow's own error is the visibility's, not the rule's.
    const int maxOrder = visible ? 16 : 64;
    while (q < maxOrder) {
      double finer[4] = {0, 0, 0, 0};
      gaussShares(point, normal, map, f.normal, 2 * q, visible, finer, out.rays);
      q *= 2;
      double change = 0;
      for (int c = 0; c < map.count; ++c)
        change = std::max(change, std::abs(finer[c] - shares[c]) * out.total);
      std::copy(finer, finer + 4, shares);
      if (change <= tolerance) break;
    }
  }
  out.order = q;
  for (int c = 0; c < map.count; ++c) out.shares[c] = out.total * shares[c];
  return out;
}

FormFactorMatrix linearKernelMatrix(const Mesh& mesh, const LinearBasis& basis,
                                    const FormFactorOptions& options, Progress& progress,
                                    FormFactorStats& stats) {
  const double tolerance = options.tolerance > 0 ? options.tolerance : kLinearKernelTolerance;
  const auto m = static_cast<Eigen::Index>(basis.size());
  FormFactorMatrix K = zeroFormFactorMatrix(m);
  const auto visibility = std::make_unique<PairVisibility>(mesh);
  // Per node: an element that uses it (its plane, its patch, the way into the patch).
  std::vector<int> owner(basis.size(), -1);
  for (std::size_t e = 0; e < mesh.size(); ++e)
    for (int c = basis.firstCorner[e]; c < basis.firstCorner[e + 1]; ++c) {
      const auto node = static_cast<std::size_t>(basis.cornerNode[static_cast<std::size_t>(c)]);
      if (owner[node] < 0) owner[node] = static_cast<int>(e);
    }
  stats.elements = mesh.size();
  forEachRow(basis.size(), options, progress, "kernel integrals (linear basis)", stats,
             [&](int v, RowCounters& counters) {
               const auto node = static_cast<std::size_t>(v);
               const Element& own = mesh.elements[static_cast<std::size_t>(owner[node])];
               const Vec3 vertex = mesh.vertices[static_cast<std::size_t>(basis.nodeVertex[node])];
               // A node on the edge of a neighbouring patch (the corner of a room) would sit on the polygon
               // it integrates over, where Lambert's formula divides by zero: the point moves into its own
               // patch by a millionth of the way to an element's centre, far below the tolerance.
               const Vec3 x = vertex + 1e-6 * (own.centroid - vertex);
               const Vec3& n = own.normal;
               for (int f = 0; f < static_cast<int>(mesh.size()); ++f) {
                 const Element& source = mesh.elements[static_cast<std::size_t>(f)];
                 if (source.patch == own.patch) continue;  // coplanar: sees nothing of it
                 // Nothing to do when the element is behind the point's plane or the point behind it.
                 if (source.normal.dot(x - source.centroid) <= 0) {
                   ++counters.pairsSkippedFacing;
                   continue;
                 }
                 const bool occluded = visibility->shafts().mayBeOccluded(x, n, own.patch, f);
                 if (!occluded) ++counters.pairsUnoccluded;
                 std::function<bool(const Vec3&)> visible;
                 if (occluded)
                   visible = [&visibility, &x, e = owner[node], f](const Vec3& y) {
                     return visibility->rays().visible(x, y, e, f);
                   };
                 const WeightedFormFactor w = weightedPointFormFactor(x, n, mesh, f, tolerance, visible);
                 ++counters.kernelEvaluations;
                 counters.raysCast += w.rays;
                 if (w.total <= 0) continue;
                 ++counters.pairsComputed;
                 const int first = basis.firstCorner[static_cast<std::size_t>(f)];
                 for (int k = 0; k < w.count; ++k)
                   K(v, basis.cornerNode[static_cast<std::size_t>(first + k)]) += w.shares[k];
               }
             });
  stats.notes = "linear basis, collocation at the nodes: " + std::to_string(m) + " nodes on " +
                std::to_string(mesh.size()) + " elements; weighted point form factors to " +
                std::to_string(tolerance) + " near the element";
  return K;
}

}  // namespace rt
