#include "viz/vertex_interpolation.h"

#include <Eigen/QR>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

namespace rt::viz {
namespace {

constexpr double kPi = 3.14159265358979323846;

double sceneScale(const Mesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  return box.isEmpty() ? 1.0 : std::max(box.diagonal().norm(), 1e-12);
}

bool sameSmoothSurface(const Mesh& mesh, int a, int b, double tolerance) {
  if (a == b) return true;
  const Element& ea = mesh.elements[a];
  const Element& eb = mesh.elements[b];
  const bool sameMaterial =
      (mesh.reflectance.row(a) - mesh.reflectance.row(b)).cwiseAbs().maxCoeff() < 1e-12 &&
      (mesh.emission.row(a) - mesh.emission.row(b)).cwiseAbs().maxCoeff() < 1e-12;
  if (!sameMaterial) return false;
  if (ea.patch == eb.patch) return true;
  // Within about a degree and a small fraction of the scene: a measured wall split into two triangles because
  // it was slightly non-planar (the Cornell box's left wall) still shades as one surface.
  return ea.normal.dot(eb.normal) > 1.0 - 1.5e-4 &&
         std::abs(ea.normal.dot(eb.centroid - ea.centroid)) < tolerance;
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

double cornerAngle(const Mesh& mesh, const Element& e, std::size_t k) {
  const std::size_t m = e.vertices.size();
  const Vec3& p = mesh.vertices[e.vertices[k]];
  const Vec3 a = mesh.vertices[e.vertices[(k + m - 1) % m]] - p;
  const Vec3 b = mesh.vertices[e.vertices[(k + 1) % m]] - p;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Open edges (used by one element of their region) binned into a uniform grid along their length, for the
// T-vertex search: a vertex lying on an edge is in a cell the edge passes or in one next to it.
class EdgeGrid {
 public:
  EdgeGrid(const Mesh& mesh, const std::vector<std::array<int, 3>>& edges, double cell) : cell_(cell) {
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const Vec3& a = mesh.vertices[edges[i][1]];
      const Vec3& b = mesh.vertices[edges[i][2]];
      const int steps = 1 + static_cast<int>(std::ceil(4 * (b - a).norm() / cell_));
      for (int k = 0; k <= steps; ++k) entries_.push_back({keyOf(a + (b - a) * (double(k) / steps)), int(i)});
    }
    std::sort(entries_.begin(), entries_.end());
    entries_.erase(std::unique(entries_.begin(), entries_.end()), entries_.end());
  }
  // Edges binned in the 27 cells around p (with repeats).
  template <typename Visit>
  void near(const Vec3& p, Visit&& visit) const {
    const Eigen::Vector3d c = (p / cell_).array().floor();
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const std::uint64_t key = pack(c + Eigen::Vector3d(dx, dy, dz));
          auto it =
              std::lower_bound(entries_.begin(), entries_.end(), std::pair<std::uint64_t, int>{key, -1});
          for (; it != entries_.end() && it->first == key; ++it) visit(it->second);
        }
  }

 private:
  std::uint64_t keyOf(const Vec3& p) const { return pack((p / cell_).array().floor()); }
  static std::uint64_t pack(const Eigen::Vector3d& c) {
    auto part = [](double v) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(v) & 0x1fffff); };
    return part(c.x()) | part(c.y()) << 21 | part(c.z()) << 42;
  }
  double cell_;
  std::vector<std::pair<std::uint64_t, int>> entries_;
};

}  // namespace

std::vector<int> smoothRegions(const Mesh& mesh) {
  const int n = static_cast<int>(mesh.size());
  const double tolerance = 2e-3 * sceneScale(mesh);
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& around : mesh.vertexElements)
    for (std::size_t i = 1; i < around.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (sameSmoothSurface(mesh, around[i], around[j], tolerance))
          parent[findRoot(parent, around[i])] = findRoot(parent, around[j]);
  // Labels in the order of each region's first element.
  std::vector<int> label(static_cast<std::size_t>(n), -1), labelOfRoot(static_cast<std::size_t>(n), -1);
  int next = 0;
  for (int e = 0; e < n; ++e) {
    int& l = labelOfRoot[findRoot(parent, e)];
    if (l < 0) l = next++;
    label[e] = l;
  }
  return label;
}

CornerField flatCornerValues(const Mesh& mesh, const RgbField& perElement) {
  CornerField field;
  field.firstCorner.assign(mesh.size() + 1, 0);
  for (std::size_t e = 0; e < mesh.size(); ++e)
    field.firstCorner[e + 1] = field.firstCorner[e] + static_cast<int>(mesh.elements[e].vertices.size());
  field.values.resize(field.firstCorner.back(), 3);
  for (std::size_t e = 0; e < mesh.size(); ++e)
    for (int k = field.firstCorner[e]; k < field.firstCorner[e + 1]; ++k)
      field.values.row(k) = perElement.row(e);
  return field;
}

CornerField smoothCornerValues(const Mesh& mesh, const RgbField& perElement) {
  return SmoothInterpolation(mesh).apply(perElement);
}

SmoothInterpolation::SmoothInterpolation(const Mesh& mesh) {
  const int n = static_cast<int>(mesh.size());
  const std::vector<int> region = smoothRegions(mesh);
  const double tolerance = 1e-6 * sceneScale(mesh);
  firstCorner_.assign(mesh.size() + 1, 0);
  for (int e = 0; e < n; ++e)
    firstCorner_[e + 1] = firstCorner_[e] + static_cast<int>(mesh.elements[e].vertices.size());

  // Slots: one per (region, vertex) that has a corner there, found through a short list per vertex.
  std::vector<int> slotRegion, slotVertex, slotNext, vertexFirstSlot(mesh.vertices.size(), -1);
  cornerSlot_.resize(static_cast<std::size_t>(firstCorner_.back()));
  for (int e = 0; e < n; ++e)
    for (std::size_t k = 0; k < mesh.elements[e].vertices.size(); ++k) {
      const int v = mesh.elements[e].vertices[k];
      int s = vertexFirstSlot[v];
      while (s >= 0 && slotRegion[s] != region[e]) s = slotNext[s];
      if (s < 0) {
        s = static_cast<int>(slotRegion.size());
        slotRegion.push_back(region[e]);
        slotVertex.push_back(v);
        slotNext.push_back(vertexFirstSlot[v]);
        vertexFirstSlot[v] = s;
      }
      cornerSlot_[firstCorner_[e] + k] = s;
    }
  const std::size_t slots = slotRegion.size();
  auto slotOf = [&](int r, int v) {
    int s = vertexFirstSlot[v];
    while (s >= 0 && slotRegion[s] != r) s = slotNext[s];
    return s;
  };

  // Per slot: the angle its region's elements cover, and those elements (in element order).
  std::vector<double> angle(slots, 0.0);
  firstTerm_.assign(slots + 1, 0);
  for (int c : cornerSlot_) ++firstTerm_[c + 1];
  for (std::size_t s = 0; s < slots; ++s) firstTerm_[s + 1] += firstTerm_[s];
  terms_.resize(cornerSlot_.size());
  {
    std::vector<int> fill(firstTerm_.begin(), firstTerm_.end() - 1);
    for (int e = 0; e < n; ++e)
      for (std::size_t k = 0; k < mesh.elements[e].vertices.size(); ++k) {
        const int s = cornerSlot_[firstCorner_[e] + k];
        angle[s] += cornerAngle(mesh, mesh.elements[e], k);
        terms_[fill[s]++].element = e;
      }
  }
  auto slotElements = [&](int s) {
    return std::pair(terms_.begin() + firstTerm_[s], terms_.begin() + firstTerm_[s + 1]);
  };

  // Open edges: used by one element of their region (the elements cornered at one end are all candidates).
  std::vector<std::array<int, 3>> open;  // region, low vertex, high vertex
  double openLength = 0;
  for (int e = 0; e < n; ++e) {
    const auto& vs = mesh.elements[e].vertices;
    for (std::size_t k = 0; k < vs.size(); ++k) {
      const int a = vs[k], b = vs[(k + 1) % vs.size()];
      int uses = 0;
      const auto [first, last] = slotElements(slotOf(region[e], a));
      for (auto t = first; t != last; ++t) {
        const auto& ws = mesh.elements[t->element].vertices;
        for (std::size_t j = 0; j < ws.size(); ++j) {
          const int c = ws[j], d = ws[(j + 1) % ws.size()];
          uses += (c == a && d == b) || (c == b && d == a);
        }
      }
      if (uses != 1) continue;
      open.push_back({region[e], std::min(a, b), std::max(a, b)});
      openLength += (mesh.vertices[b] - mesh.vertices[a]).norm();
    }
  }
  // T-vertices: a boundary vertex of the region strictly inside an open edge of the same region; of
  // several, the edge with the lowest vertex indices.
  if (!open.empty()) {
    const EdgeGrid grid(mesh, open, std::max(openLength / static_cast<double>(open.size()), 1e3 * tolerance));
    for (std::size_t s = 0; s < slots; ++s) {
      if (angle[s] > 2 * kPi - 1e-6) continue;
      const int v = slotVertex[s];
      const Vec3& p = mesh.vertices[v];
      int best = -1;
      double bestT = 0;
      grid.near(p, [&](int i) {
        const auto& [r, a, b] = open[static_cast<std::size_t>(i)];
        if (r != slotRegion[s] || a == v || b == v) return;
        if (best >= 0 && std::pair(a, b) >= std::pair(open[best][1], open[best][2])) return;
        const Vec3 ab = mesh.vertices[b] - mesh.vertices[a];
        const double t = ab.dot(p - mesh.vertices[a]) / ab.squaredNorm();
        if (t <= 1e-9 || t >= 1 - 1e-9) return;
        if ((mesh.vertices[a] + t * ab - p).norm() > tolerance) return;
        best = i;
        bestT = t;
      });
      if (best < 0) continue;
      const auto& [r, a, b] = open[static_cast<std::size_t>(best)];
      tVertices_.push_back({static_cast<int>(s), slotOf(r, a), slotOf(r, b), bestT});
      angle[s] += kPi;  // the larger element covers the other half-plane
    }
    std::sort(tVertices_.begin(), tVertices_.end(), [&](const TVertex& x, const TVertex& y) {
      return std::pair(slotRegion[x.slot], slotVertex[x.slot]) <
             std::pair(slotRegion[y.slot], slotVertex[y.slot]);
    });
  }

  // Boundary slots extrapolate through each element around them, B_e + g_e . (v - c_e), with g_e the
  // least-squares gradient from the centroids of e's neighbours in the region. On a regular grid this is the
  // classic 2 B_e - B_interior of the book; in general it is exact for a linear field on any mesh. g_e is
  // linear in the neighbours' differences, so each extrapolation is a weighted sum of them: the weights,
  // offset^T pinv(A), are all that is kept.
  extrapolated_.assign(slots, 0);
  std::vector<std::vector<int>> neighbourCache(mesh.size());
  std::vector<Eigen::Matrix3Xd> pinvCache(mesh.size());
  std::vector<char> cached(mesh.size(), 0);
  for (std::size_t s = 0; s < slots; ++s) {
    if (angle[s] > 2 * kPi - 1e-6) continue;
    extrapolated_[s] = 1;
    for (int t = firstTerm_[s]; t < firstTerm_[s + 1]; ++t) {
      const int e = terms_[t].element;
      if (!cached[e]) {
        cached[e] = 1;
        std::vector<int>& neighbours = neighbourCache[e];
        for (int v : mesh.elements[e].vertices)
          for (int other : mesh.vertexElements[v])
            if (other != e && region[other] == region[e] &&
                std::find(neighbours.begin(), neighbours.end(), other) == neighbours.end())
              neighbours.push_back(other);
        if (!neighbours.empty()) {
          Eigen::MatrixXd A(static_cast<Eigen::Index>(neighbours.size()), 3);
          for (Eigen::Index k = 0; k < A.rows(); ++k)
            A.row(k) = (mesh.elements[neighbours[k]].centroid - mesh.elements[e].centroid).transpose();
          // Minimum-norm solution: no gradient along the normal, and none across a strip one element wide.
          // A strip's centroids are collinear only up to the file's rounding (1e-6 of a 5 cm element in the
          // museum): with Eigen's default threshold that direction counts, and its gradient extrapolates
          // to 1e12. Directions below a thousandth of the largest are dropped instead.
          Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A.rows(), A.cols());
          cod.setThreshold(1e-3);
          cod.compute(A);
          pinvCache[e] = cod.pseudoInverse();
        }
      }
      terms_[t].firstWeight = static_cast<int>(weights_.size());
      const Vec3 offset = mesh.vertices[slotVertex[s]] - mesh.elements[e].centroid;
      const std::vector<int>& neighbours = neighbourCache[e];
      if (!neighbours.empty()) {
        const Eigen::VectorXd w = pinvCache[e].transpose() * offset;
        for (std::size_t k = 0; k < neighbours.size(); ++k) {
          neighbours_.push_back(neighbours[k]);
          weights_.push_back(w[static_cast<Eigen::Index>(k)]);
        }
      }
      terms_[t].lastWeight = static_cast<int>(weights_.size());
    }
  }
}

CornerField SmoothInterpolation::apply(const RgbField& perElement) const {
  const std::size_t slots = extrapolated_.size();
  std::vector<Rgb> value(slots);
  for (std::size_t s = 0; s < slots; ++s) {
    Rgb sum = Rgb::Zero();
    for (int t = firstTerm_[s]; t < firstTerm_[s + 1]; ++t) {
      const Term& term = terms_[t];
      const Rgb own = perElement.row(term.element).transpose().array();
      if (!extrapolated_[s]) {
        sum += own;
        continue;
      }
      Rgb extrapolated = own;
      for (int k = term.firstWeight; k < term.lastWeight; ++k)
        extrapolated += weights_[k] * (perElement.row(neighbours_[k]).transpose().array() - own);
      sum += extrapolated.max(0.0);
    }
    value[s] = sum / static_cast<double>(firstTerm_[s + 1] - firstTerm_[s]);
  }
  // T-vertices last: along the long edge (twice, for T-vertices whose edge ends at another T-vertex).
  for (int pass = 0; pass < 2; ++pass)
    for (const TVertex& tv : tVertices_) value[tv.slot] = (1 - tv.t) * value[tv.a] + tv.t * value[tv.b];

  CornerField field;
  field.firstCorner = firstCorner_;
  field.values.resize(static_cast<Eigen::Index>(cornerSlot_.size()), 3);
  for (std::size_t c = 0; c < cornerSlot_.size(); ++c)
    field.values.row(static_cast<Eigen::Index>(c)) = value[cornerSlot_[c]].transpose();
  return field;
}

}  // namespace rt::viz
