#include "core/solvers/cluster_links.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/formfactor/analytic.h"
#include "core/formfactor/sampling.h"
#include "core/parallel.h"

namespace rt {
namespace {

struct Pair {
  int receiver, source;
};

// An element's corners as an array, for the allocation-free analytic form factors.
struct Corners {
  Vec3 at[8];
  int count = 0;
};

Corners cornersOf(const Mesh& mesh, int e) {
  const Element& element = mesh.elements[static_cast<std::size_t>(e)];
  Corners c;
  c.count = static_cast<int>(std::min<std::size_t>(element.vertices.size(), 8));
  for (int k = 0; k < c.count; ++k) c.at[k] = mesh.vertices[static_cast<std::size_t>(element.vertices[k])];
  return c;
}

// The largest cosine between `normal` and a direction within the cone about `axis` (unit) of half-angle
// asin(sinHalf): 1 when the cone contains the normal.
double coneCosine(const Vec3& normal, const Vec3& axis, double sinHalf) {
  if (sinHalf >= 1.0) return 1.0;
  const double theta = std::acos(std::clamp(normal.dot(axis), -1.0, 1.0));
  const double below = theta - std::asin(sinHalf);
  if (below <= 0.0) return 1.0;
  return below >= std::numbers::pi / 2 ? 0.0 : std::cos(below);
}

class Oracle {
 public:
  Oracle(const ClusterTree& tree, const Mesh& mesh, const RayScene& scene,
         const std::vector<double>& brightness, const LinkRefinement& options)
      : tree_(tree), mesh_(mesh), scene_(scene), brightness_(brightness), options_(options) {}

  // One pair: a link, the pairs of a split, or nothing (it cannot carry light).
  void visit(Pair p, std::vector<ClusterLink>& links, std::vector<Pair>& next, long& rays) const {
    const ClusterNode& r = tree_.node(p.receiver);
    const ClusterNode& s = tree_.node(p.source);
    if (p.receiver == p.source) {
      if (r.leaf()) return;  // a planar element does not see itself
      next.push_back({r.left, r.left});
      next.push_back({r.left, r.right});
      next.push_back({r.right, r.left});
      next.push_back({r.right, r.right});
      return;
    }
    const double b = brightness_[static_cast<std::size_t>(p.source)];
    if (r.rhoMax <= 0.0f || b <= 0.0) return;
    if (r.leaf() && behind(s.box, r.element)) return;
    if (s.leaf() && behind(r.box, s.element)) return;
    const Vec3 d = s.centroid - r.centroid;
    const double distance = d.norm();
    const bool elements = r.leaf() && s.leaf();
    if (!elements) {
      const double gap = distance - r.radius - s.radius;
      if (gap <= 0.0) return split(p, r, s, next);
      const Vec3 u = d / distance;
      const double sinHalf = (r.radius + s.radius) / distance;
      const double cosR = r.leaf() ? coneCosine(normalOf(r.element), u, sinHalf) : 1.0;
      const double cosS = s.leaf() ? coneCosine(normalOf(s.element), -u, sinHalf) : 1.0;
      const double bound = std::min(1.0, s.area * cosR * cosS / (std::numbers::pi * gap * gap));
      if (bound <= 0.0) return;
      if (double(r.rhoMax) * b * bound > options_.threshold) return split(p, r, s, next);
    }
    const double K = estimate(r, s, d, distance);
    // Zero from the centroids' directions while the bound is not: part of a cluster may still face the
    // other node, so look closer rather than drop the light.
    if (!(K > 0.0)) {
      if (!elements) split(p, r, s, next);
      return;
    }
    const double visible = visibleFraction(p, rays);
    if (visible <= 0.0) return;
    const Vec3 u = d / distance;
    links.push_back({p.receiver,
                     p.source,
                     static_cast<float>(K * visible),
                     {static_cast<float>(u.x()), static_cast<float>(u.y()), static_cast<float>(u.z())}});
  }

 private:
  Vec3 normalOf(int e) const { return mesh_.elements[static_cast<std::size_t>(e)].normal.normalized(); }

  // The whole box lies on or behind the plane of element e: nothing in it can send light to e's front or
  // receive light from it.
  bool behind(const Eigen::AlignedBox3d& box, int e) const {
    const Element& element = mesh_.elements[static_cast<std::size_t>(e)];
    const Vec3 n = element.normal.normalized();
    const double slack = 1e-9 * (box.diagonal().norm() + std::sqrt(element.area));
    for (int corner = 0; corner < 8; ++corner)
      if (n.dot(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)) - element.centroid) > slack)
        return false;
    return true;
  }

  // Split the larger node (by sphere) that can be split.
  static void split(Pair p, const ClusterNode& r, const ClusterNode& s, std::vector<Pair>& next) {
    if (!r.leaf() && (s.leaf() || r.radius >= s.radius)) {
      next.push_back({r.left, p.source});
      next.push_back({r.right, p.source});
    } else {
      next.push_back({p.receiver, s.left});
      next.push_back({p.receiver, s.right});
    }
  }

  double estimate(const ClusterNode& r, const ClusterNode& s, const Vec3& d, double distance) const {
    if (r.leaf() && s.leaf()) {
      const Corners cs = cornersOf(mesh_, s.element);
      if (distance < 2.0 * (r.radius + s.radius)) {
        const Corners cr = cornersOf(mesh_, r.element);
        return polygonToPolygonFormFactor(cr.at, cr.count, cs.at, cs.count);
      }
      return pointToPolygonFormFactor(r.centroid, normalOf(r.element), cs.at, cs.count);
    }
    // A source cluster's intensity comes from its normal classes at solve time, so only the distance and
    // the receiver's cosine belong here.
    const Vec3 u = d / distance;
    const double source =
        s.leaf() ? s.area * std::max(0.0, -normalOf(s.element).dot(u)) / std::numbers::pi : 1.0;
    const double receiver = r.leaf() ? std::max(0.0, normalOf(r.element).dot(u)) : 1.0;
    return source * receiver / (distance * distance);
  }

  // The fraction of a few segments between random points of the two nodes that nothing blocks. Elements
  // are drawn by area (the draws stratified), and only pairs of points whose elements face each other count:
  // the normal classes already leave out the elements of a cluster that face away, so a segment to the
  // back of a partition or of a plinth, blocked by its own front, must not count as shadow. A pair that
  // faces away is drawn again, a few times at most; when none faces, the nodes exchange nothing.
  double visibleFraction(Pair p, long& rays) const {
    constexpr int kTries = 8;
    const int m = std::max(1, options_.visibilityRays);
    PairRandom random(options_.seed, static_cast<std::uint64_t>(p.receiver),
                      static_cast<std::uint64_t>(p.source));
    int visible = 0, cast = 0;
    for (int k = 0; k < m; ++k)
      for (int attempt = 0; attempt < kTries; ++attempt) {
        const int er = tree_.sampleElement(p.receiver, (k + random.uniform()) / m);
        const int es = tree_.sampleElement(p.source, (k + random.uniform()) / m);
        const Corners cr = cornersOf(mesh_, er), cs = cornersOf(mesh_, es);
        const double a = random.uniform(), b = random.uniform(), c = random.uniform(), e = random.uniform();
        const Vec3 from = pointOnPolygon(cr.at, cr.count, a, b);
        const Vec3 to = pointOnPolygon(cs.at, cs.count, c, e);
        const Vec3 d = to - from;
        if (!(mesh_.elements[static_cast<std::size_t>(er)].normal.dot(d) > 0.0) ||
            !(mesh_.elements[static_cast<std::size_t>(es)].normal.dot(d) < 0.0))
          continue;
        ++cast;
        if (scene_.visible(from, to, er, es)) ++visible;
        break;
      }
    rays += cast;
    return cast > 0 ? double(visible) / cast : 0.0;
  }

  const ClusterTree& tree_;
  const Mesh& mesh_;
  const RayScene& scene_;
  const std::vector<double>& brightness_;
  const LinkRefinement& options_;
};

}  // namespace

std::vector<ClusterLink> refineLinks(const ClusterTree& tree, const Mesh& mesh, const RayScene& scene,
                                     const std::vector<double>& brightness, const LinkRefinement& options,
                                     std::atomic<long>& rays) {
  std::vector<ClusterLink> links;
  if (tree.size() == 0) return links;
  const Oracle oracle(tree, mesh, scene, brightness, options);
  PerWorker<std::vector<ClusterLink>> found;
  std::vector<Pair> frontier{{0, 0}};
  // Level by level: every pair of a level is decided independently, so the level runs in parallel.
  while (!frontier.empty()) {
    PerWorker<std::vector<Pair>> next;
    parallelForChunks(0, frontier.size(), {.grain = 64}, [&](std::size_t lo, std::size_t hi) {
      auto& mine = found.local();
      auto& children = next.local();
      long cast = 0;
      for (std::size_t k = lo; k != hi; ++k) oracle.visit(frontier[k], mine, children, cast);
      rays += cast;
    });
    frontier.clear();
    next.forEach(
        [&](const std::vector<Pair>& part) { frontier.insert(frontier.end(), part.begin(), part.end()); });
  }
  std::size_t total = 0;
  found.forEach([&](const std::vector<ClusterLink>& part) { total += part.size(); });
  links.reserve(total);
  found.forEach([&](std::vector<ClusterLink>& part) {
    links.insert(links.end(), part.begin(), part.end());
    std::vector<ClusterLink>().swap(part);
  });
  parallelSort(links.begin(), links.end(), [](const ClusterLink& a, const ClusterLink& b) {
    return a.receiver < b.receiver || (a.receiver == b.receiver && a.source < b.source);
  });
  return links;
}

}  // namespace rt
