// Hierarchical radiosity (Hanrahan, Salzman & Aupperle 1991). Each patch is the root of an element quadtree.
// For every ordered pair of patches, Refine(p, q) decides whether node p may gather from node q through one
// link: when the estimated transfer is small enough it links them, otherwise it splits the node that looks
// larger from the other (the one with the larger form-factor estimate towards it) and recurses on its
// children. Solving gathers along the links at every level and then push-pulls: gathered radiosity is pushed
// down to the leaves, the leaves' radiosities are area-averaged back up. With the brightness-weighted ("BF")
// oracle, links are rebuilt after each solve using the new radiosities, so interreflection between bright
// walls is refined only once it is known to matter.
#include <algorithm>
#include <chrono>

#include "core/polygon.h"
#include "core/refine/piece_mesh.h"
#include "core/refine/refine_modes.h"
#include "core/refine/transfer.h"

namespace rt {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}
using Row = Eigen::RowVector3d;

// Links that are partly shadowed are kept only when their brightness-weighted transfer is this much below the
// tolerance: shadow boundaries then get refined further than smooth regions.
constexpr double kPartialVisibilityFactor = 0.1;

struct Node {
  Polygon polygon;
  Vec3 normal, centroid;
  double area = 0;
  int patch = -1;
  int level = 0;
  std::vector<int> children;
  Row B = Row::Zero(), gathered = Row::Zero(), emission = Row::Zero(), reflectance = Row::Zero();
  struct Link {
    int source;
    double F;
  };
  std::vector<Link> links;  // this node gathers F * B_source from each source
};

class Hierarchy {
 public:
  Hierarchy(const Scene& scene, const RefineOptions& options) : options_(options), visibility_(scene) {
    transfer_.visibilitySamples = options.visibilitySamples;
    for (std::size_t p = 0; p < scene.patches.size(); ++p) {
      const Patch& patch = scene.patches[p];
      const Material& m = scene.materialOf(patch);
      Node root;
      root.polygon = patch.vertices;
      root.normal = patch.normal;
      root.centroid = polygonCentroid(patch.vertices);
      root.area = polygonArea(patch.vertices);
      root.patch = static_cast<int>(p);
      root.emission = m.emission.matrix().transpose();
      root.reflectance = m.reflectance.matrix().transpose();
      root.B = root.emission;
      nodes_.push_back(std::move(root));
      brightest_ = std::max(brightest_, luminance(nodes_.back().emission));
    }
    roots_ = static_cast<int>(nodes_.size());
  }

  // Rebuilds every link from the patch pairs down, with the current radiosities in the oracle.
  void buildLinks(Progress& progress) {
    for (Node& n : nodes_) n.links.clear();
    links_ = 0;
    for (int p = 0; p < roots_; ++p) {
      if (progress.cancelled()) throw Cancelled();
      progress.report(static_cast<double>(p) / roots_, "links");
      for (int q = 0; q < roots_; ++q)
        if (p != q) refine(p, q);
    }
  }

  // Gather over all links, push-pull, until the largest change is below the tolerance. Returns the sweeps.
  int solve(Progress& progress) {
    for (int sweep = 1; sweep <= options_.maxSweeps; ++sweep) {
      if (progress.cancelled()) throw Cancelled();
      for (Node& n : nodes_) {
        n.gathered = Row::Zero();
        for (const Node::Link& l : n.links) n.gathered += l.F * nodes_[l.source].B;
      }
      double change = 0, largest = 0;
      for (int r = 0; r < roots_; ++r) pushPull(r, Row::Zero(), change);
      for (const Node& n : nodes_) largest = std::max(largest, n.B.cwiseAbs().maxCoeff());
      if (change <= options_.solverTolerance * std::max(largest, 1e-300)) return sweep;
    }
    return options_.maxSweeps;
  }

  const std::vector<Node>& nodes() const { return nodes_; }
  std::size_t links() const { return links_; }
  std::size_t oracleCalls() const { return oracleCalls_; }
  std::size_t raysCast() const { return visibility_.raysCast(); }

 private:
  SurfacePiece piece(int n) const {
    const Node& node = nodes_[n];
    return {&node.polygon, node.normal, node.centroid, node.area, node.patch};
  }
  double weight(int n) const {
    if (!options_.brightnessWeighted || brightest_ <= 0) return 1.0;
    return luminance(nodes_[n].B) / brightest_;
  }
  bool canSplit(int n) const { return nodes_[n].area / 4 >= options_.minArea; }

  void split(int n) {
    if (!nodes_[n].children.empty()) return;
    const Polygon polygon = nodes_[n].polygon;
    const std::vector<Polygon> parts = polygon.size() <= 4 ? splitInFour(polygon) : fanTriangulate(polygon);
    for (const Polygon& part : parts) {
      Node child;
      child.polygon = part;
      child.normal = nodes_[n].normal;
      child.centroid = polygonCentroid(part);
      child.area = polygonArea(part);
      child.patch = nodes_[n].patch;
      child.level = nodes_[n].level + 1;
      child.emission = nodes_[n].emission;
      child.reflectance = nodes_[n].reflectance;
      child.B = nodes_[n].B;
      nodes_.push_back(std::move(child));
      nodes_[n].children.push_back(static_cast<int>(nodes_.size() - 1));
    }
  }

  // p gathers from q.
  void refine(int p, int q) {
    ++oracleCalls_;
    const auto [fpq, fqp] = pieceFormFactorEstimate(piece(p), piece(q));
    if (fpq <= 0 && fqp <= 0) return;  // they do not see each other at all
    const double w = weight(q);
    const double error = w * std::max(fpq, fqp);
    bool acceptable = error < options_.linkTolerance;
    if (acceptable && error >= kPartialVisibilityFactor * options_.linkTolerance && partlyVisible(p, q))
      acceptable = false;
    if (!acceptable) {
      // Split the node that subtends more from the other: fqp large means p looks large from q.
      const bool splitReceiver = fqp >= fpq ? canSplit(p) : !canSplit(q) && canSplit(p);
      const bool splitSource = !splitReceiver && canSplit(q);
      if (splitReceiver) {
        split(p);
        for (int c : std::vector<int>(nodes_[p].children)) refine(c, q);
        return;
      }
      if (splitSource) {
        split(q);
        for (int c : std::vector<int>(nodes_[q].children)) refine(p, c);
        return;
      }
    }
    const double F = pieceFormFactors(piece(p), piece(q), visibility_, transfer_).first;
    if (F <= 0) return;
    nodes_[p].links.push_back({q, F});
    ++links_;
  }

  bool partlyVisible(int p, int q) const {
    if (!visibility_.mayBeOccluded(nodes_[p].patch, nodes_[q].patch)) return false;
    const auto onQ = stratifiedSamples(nodes_[q].polygon, 2);
    const auto onP = stratifiedSamples(nodes_[p].polygon, 2);
    const double a = visibility_.visibleFraction(nodes_[p].centroid, onQ, nodes_[p].patch, nodes_[q].patch);
    const double b = visibility_.visibleFraction(nodes_[q].centroid, onP, nodes_[q].patch, nodes_[p].patch);
    auto partial = [](double v) { return v > 0 && v < 1; };
    return partial(a) || partial(b) || (a == 0) != (b == 0);
  }

  Row pushPull(int n, const Row& fromAbove, double& change) {
    Node& node = nodes_[n];
    const Row down = fromAbove + node.gathered;
    Row next;
    if (node.children.empty()) {
      next = node.emission + (node.reflectance.array() * down.array()).matrix();
    } else {
      next = Row::Zero();
      for (int c : node.children) {
        const Row b = pushPull(c, down, change);
        next += b * (nodes_[c].area / node.area);
      }
    }
    change = std::max(change, (next - nodes_[n].B).cwiseAbs().maxCoeff());
    nodes_[n].B = next;
    return next;
  }

  RefineOptions options_;
  VisibilityOracle visibility_;
  TransferOptions transfer_;
  std::vector<Node> nodes_;
  int roots_ = 0;
  double brightest_ = 0;
  std::size_t links_ = 0;
  std::size_t oracleCalls_ = 0;
};

}  // namespace

RefinedSolution solveHierarchical(const Scene& scene, const RefineOptions& options, Progress& progress) {
  const auto start = Clock::now();
  RefinedSolution solution;
  solution.stats.mode = options.mode;
  solution.stats.initialElements = scene.patches.size();
  Hierarchy hierarchy(scene, options);
  const int rounds = options.brightnessWeighted ? std::max(1, options.refinementRounds) : 1;
  for (int round = 0; round < rounds; ++round) {
    RefinePass pass;
    const auto linkStart = Clock::now();
    const std::size_t callsBefore = hierarchy.oracleCalls();
    hierarchy.buildLinks(progress);
    solution.stats.formFactorSeconds += secondsSince(linkStart);
    const auto solveStart = Clock::now();
    pass.sweeps = hierarchy.solve(progress);
    solution.stats.solveSeconds += secondsSince(solveStart);
    pass.pairsComputed = hierarchy.oracleCalls() - callsBefore;
    pass.seconds = secondsSince(linkStart);
    for (const Node& n : hierarchy.nodes()) pass.elements += n.children.empty();
    solution.stats.passes.push_back(pass);
  }

  const std::vector<Node>& nodes = hierarchy.nodes();
  std::vector<Polygon> pieces;
  std::vector<int> patchOf;
  std::vector<int> leafOf(nodes.size(), -1);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    if (!nodes[n].children.empty()) continue;
    leafOf[n] = static_cast<int>(pieces.size());
    pieces.push_back(nodes[n].polygon);
    patchOf.push_back(nodes[n].patch);
    solution.elementLevel.push_back(nodes[n].level);
    solution.stats.maxLevel = std::max(solution.stats.maxLevel, nodes[n].level);
  }
  solution.mesh = meshFromPieces(scene, pieces, patchOf);
  solution.B.resize(static_cast<Eigen::Index>(pieces.size()), 3);
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (leafOf[n] >= 0) solution.B.row(leafOf[n]) = nodes[n].B;
  for (std::size_t n = 0; n < nodes.size(); ++n)
    for (const Node::Link& l : nodes[n].links)
      solution.links.push_back(
          {nodes[l.source].polygon, nodes[n].polygon, nodes[l.source].level, nodes[n].level, l.F});
  solution.tVertices = findTVertices(solution.mesh);
  solution.stats.elements = solution.mesh.size();
  solution.stats.links = hierarchy.links();
  solution.stats.hierarchyNodes = nodes.size();
  for (const RefinePass& p : solution.stats.passes) solution.stats.pairsComputed += p.pairsComputed;
  solution.stats.tVertices = solution.tVertices.size();
  solution.stats.raysCast = hierarchy.raysCast();
  solution.stats.seconds = secondsSince(start);
  return solution;
}

}  // namespace rt
