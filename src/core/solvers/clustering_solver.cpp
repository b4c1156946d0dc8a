#include "core/solvers/clustering_solver.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/formfactor/ray_scene.h"
#include "core/parallel.h"
#include "core/solvers/cluster_directions.h"
#include "core/solvers/cluster_links.h"
#include "core/solvers/cluster_tree.h"
#include "core/solvers/solver_support.h"

namespace rt {
namespace {

using namespace solver_detail;
using Row = Eigen::RowVector3d;

// Links grouped by receiver: the receivers in order, and where each one's links start.
struct LinkTable {
  std::vector<ClusterLink> links;
  std::vector<int> receivers;
  std::vector<std::size_t> starts;  // receivers.size() + 1 entries

  explicit LinkTable(std::vector<ClusterLink> sorted) : links(std::move(sorted)) {
    for (std::size_t k = 0; k < links.size(); ++k)
      if (k == 0 || links[k].receiver != links[k - 1].receiver) {
        receivers.push_back(links[k].receiver);
        starts.push_back(k);
      }
    starts.push_back(links.size());
  }
  std::size_t bytes() const {
    return links.capacity() * sizeof(ClusterLink) + receivers.capacity() * sizeof(int) +
           starts.capacity() * sizeof(std::size_t);
  }
};

// Per node, 3 channels for each normal class (cluster_directions.h), class-major; at most 36 columns, so a
// row on the stack needs no allocation.
using Bins = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using BinRow =
    Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, 3 * ClusterDirections::kMaxClasses>;

// The state of one solve on the tree: per node its radiosity (area-weighted mean), its directional power
// D, and the irradiance it gathered (scalar on an element, in bins on a cluster).
class HierarchySolve {
 public:
  HierarchySolve(const RadiositySystem& system, const ClusterTree& tree)
      : system_(system),
        tree_(tree),
        directions_(*system.mesh),
        columns_(3 * directions_.classes()),
        B_(tree.size(), 3),
        H_(tree.size(), 3),
        D_(tree.size(), columns_),
        bins_(tree.size(), columns_),
        below_(tree.size(), columns_) {
    leaf_.resize(tree.size());
    for (std::size_t k = 0; k < tree.size(); ++k) leaf_[k] = tree.nodes()[k].leaf();
  }

  // Element radiosities in; node radiosities and directional powers out.
  void pull(const RgbField& elements) {
    const auto& nodes = tree_.nodes();
    for (std::size_t k = nodes.size(); k-- > 0;) {
      const ClusterNode& node = nodes[k];
      const auto K = Eigen::Index(k);
      if (node.leaf()) {
        B_.row(K) = elements.row(node.element);
        D_.row(K).setZero();
        const Row power = elements.row(node.element) * node.area;
        directions_.spread(node.element, power.data(), D_.row(K).data());
      } else {
        const ClusterNode& l = nodes[std::size_t(node.left)];
        const ClusterNode& r = nodes[std::size_t(node.right)];
        B_.row(K) = node.area > 0
                        ? Row((l.area * B_.row(node.left) + r.area * B_.row(node.right)) / node.area)
                        : Row(0.5 * (B_.row(node.left) + B_.row(node.right)));
        D_.row(K) = D_.row(node.left) + D_.row(node.right);
      }
    }
  }

  // One sweep: gather along the links from the current node radiosities, push the irradiance down to the
  // elements, and return their new radiosities.
  RgbField sweep(const LinkTable& table) {
    H_.setZero();  // nodes that receive nothing this round
    bins_.setZero();
    parallelForChunks(0, table.receivers.size(), {.grain = 256}, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t k = lo; k != hi; ++k) gather(table, k);
    });
    const auto& nodes = tree_.nodes();
    RgbField elements(system_.size(), 3);
    below_.row(0) = bins_.row(0);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const ClusterNode& node = nodes[k];
      const auto K = Eigen::Index(k);
      if (node.leaf()) {
        Row picked;
        directions_.pick(node.element, below_.row(K).data(), picked.data());
        const Row irradiance = H_.row(K) + picked;
        elements.row(node.element) = system_.emission.row(node.element) +
                                     system_.reflectance.row(node.element).cwiseProduct(irradiance);
        continue;
      }
      below_.row(node.left) = below_.row(K) + bins_.row(node.left);
      below_.row(node.right) = below_.row(K) + bins_.row(node.right);
    }
    return elements;
  }

  // Per node, the largest channel of its area-mean radiosity: the oracle's brightness.
  std::vector<double> brightness() const {
    std::vector<double> b(tree_.size());
    for (std::size_t k = 0; k < b.size(); ++k) b[k] = B_.row(Eigen::Index(k)).maxCoeff();
    return b;
  }
  std::size_t bytes() const {
    return sizeof(double) *
               static_cast<std::size_t>(B_.size() + H_.size() + D_.size() + bins_.size() + below_.size()) +
           directions_.bytes() + leaf_.capacity();
  }

 private:
  // All links of the k-th receiver: what each source sends towards it, collected as a scalar irradiance on
  // an element and per normal class on a cluster. Each receiver is written by one task only.
  void gather(const LinkTable& table, std::size_t k) {
    const int receiver = table.receivers[k];
    const bool element = leaf_[std::size_t(receiver)] != 0;
    Row scalar = Row::Zero();
    BinRow bins = BinRow::Zero(columns_);
    for (std::size_t l = table.starts[k]; l < table.starts[k + 1]; ++l) {
      const ClusterLink& link = table.links[l];
      const Vec3 u(link.direction[0], link.direction[1], link.direction[2]);
      Row sent;
      if (leaf_[std::size_t(link.source)]) {
        sent = B_.row(link.source);  // K holds the source's area and cosine
      } else {
        // Intensity x pi towards -u from the source's classes.
        directions_.radiate(D_.row(link.source).data(), -u, sent.data());
        sent /= std::numbers::pi;
      }
      const Row E = double(link.K) * sent;
      if (element)
        scalar += E;
      else
        directions_.receive(E.data(), u, bins.data());
    }
    H_.row(receiver) = scalar;
    bins_.row(receiver) = bins;
  }

  const RadiositySystem& system_;
  const ClusterTree& tree_;
  const ClusterDirections directions_;
  const Eigen::Index columns_;
  RgbField B_, H_;
  Bins D_, bins_, below_;
  std::vector<char> leaf_;
};

// Area-weighted mean over the elements of the largest channel.
double meanBrightness(const RgbField& B, const Eigen::VectorXd& areas) {
  return B.rowwise().maxCoeff().dot(areas) / areas.sum();
}

// The radiosity guessed before anything is solved: E plus rho times the ambient term, the light every
// element would get if the emitted power were spread evenly and reflected with the mean reflectance.
RgbField ambientGuess(const RadiositySystem& system) {
  const Eigen::VectorXd& A = system.areas;
  const double area = A.sum();
  const Row emitted = (system.emission.transpose() * A).transpose() / area;
  const Row rho = ((system.reflectance.transpose() * A).transpose() / area).cwiseMin(0.99);
  const Row ambient = emitted.cwiseQuotient((Row::Ones() - rho));
  RgbField guess = system.emission;
  for (Eigen::Index i = 0; i < guess.rows(); ++i)
    guess.row(i) += system.reflectance.row(i).cwiseProduct(ambient);
  return guess;
}

}  // namespace

double defaultClusterTolerance() {
  return 0.05;
}

SolverStatus hierarchicalClustering(const RadiositySystem& system, RgbField& B, const SolverOptions& options,
                                    const IterationSink& sink, RgbField* errorEstimate) {
  B = system.emission;
  if (errorEstimate) *errorEstimate = RgbField::Zero(system.emission.rows(), 3);
  const SolverStatus valid = validate(system, false);
  if (valid != SolverStatus::Success) return valid;
  if (!system.mesh || system.mesh->size() != system.size()) return SolverStatus::InvalidInput;
  const Stopwatch clock;
  const Mesh& mesh = *system.mesh;
  const ClusterTree tree(mesh, system.reflectance);
  const RayScene scene(mesh);
  HierarchySolve solve(system, tree);
  const double epsilon = options.clusterTolerance > 0 ? options.clusterTolerance : defaultClusterTolerance();
  const double emitted = totalEmittedPower(system);
  const double q = std::min(system.reflectance.maxCoeff(), 0.9999);
  std::atomic<long> rays{0};
  std::size_t peakBytes = 0;
  int iteration = 0;
  const int cap = sweepCap(options);

  RgbField first, change;
  for (int round = 0; round < 2; ++round) {
    const RgbField& known = round == 0 ? ambientGuess(system) : B;
    solve.pull(known);
    LinkRefinement refinement;
    refinement.threshold = (round == 0 ? epsilon : epsilon / 4) * meanBrightness(known, system.areas);
    refinement.seed = options.seed + static_cast<std::uint64_t>(round);
    const LinkTable table(refineLinks(tree, mesh, scene, solve.brightness(), refinement, rays));
    const std::size_t bytes = tree.bytes() + table.bytes() + solve.bytes();
    peakBytes = std::max(peakBytes, bytes);
    solve.pull(B);
    for (;;) {
      RgbField next = solve.sweep(table);
      change = next - B;
      B = std::move(next);
      solve.pull(B);
      IterationRecord rec;
      rec.iteration = ++iteration;
      rec.B = B;
      const double norm = B.norm();
      rec.residual = norm > 0 ? change.norm() / norm : change.norm();
      rec.emittedPower = emitted;
      rec.seconds = clock.seconds();
      rec.rays = rays.load();
      rec.links = static_cast<long>(table.links.size());
      rec.nodes = static_cast<long>(tree.size());
      rec.memoryBytes = static_cast<long long>(peakBytes);
      const bool converged = rec.residual <= options.tolerance;
      if (!B.allFinite()) return SolverStatus::NumericalIssue;
      if (round == 1 || !converged || iteration >= cap) {
        // The estimate as it stands: the change from the first round (zero before there is one), the
        // Jacobi tail of this sweep's change, and the links' float rounding (2^-24 of every transfer, all
        // of which add up to at most the largest B - E, carried through the bounces).
        const Row rounding = (B - system.emission).cwiseAbs().colwise().maxCoeff() * (0x1p-24 / (1.0 - q));
        const Row tail = change.cwiseAbs().colwise().maxCoeff() * (q / (1.0 - q)) + rounding;
        RgbField estimate = round == 1 ? RgbField(2.0 * (B - first).cwiseAbs()) : RgbField::Zero(B.rows(), 3);
        estimate.rowwise() += tail;
        rec.standardError = relativeAreaRms(estimate, B, system.areas);
        if (errorEstimate) *errorEstimate = std::move(estimate);
      }
      if (sink) sink(std::move(rec));
      if (converged) break;
      if (iteration >= cap) return SolverStatus::NoConvergence;
    }
    if (round == 0) first = B;
  }
  return SolverStatus::Success;
}

}  // namespace rt
