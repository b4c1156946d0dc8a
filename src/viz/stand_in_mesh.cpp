#include "viz/stand_in_mesh.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace rt::viz {
namespace {

constexpr std::uint8_t kUnpainted = 200;  // as the full mesh's cells without paint (element_polydata.cpp)
constexpr int kClusterBits = 21;          // a triangle's three cluster ids packed into one 64-bit key

// The facing of an element: the dominant axis of its normal and its sign (0..5).
std::uint64_t facing(const Vec3& normal) {
  Eigen::Index axis = 0;
  normal.cwiseAbs().maxCoeff(&axis);
  return static_cast<std::uint64_t>(2 * axis + (normal[axis] < 0 ? 1 : 0));
}

// The plane quadrics of the elements around a bin, summed: sum w n n^T (6 values) and sum w d n (3).
struct Quadric {
  std::array<double, 9> q{};
  void add(const Vec3& n, double d, double w) {
    q[0] += w * n.x() * n.x(), q[1] += w * n.x() * n.y(), q[2] += w * n.x() * n.z();
    q[3] += w * n.y() * n.y(), q[4] += w * n.y() * n.z(), q[5] += w * n.z() * n.z();
    q[6] += w * d * n.x(), q[7] += w * d * n.y(), q[8] += w * d * n.z();
  }
  void add(const Quadric& o) {
    for (std::size_t i = 0; i < q.size(); ++i) q[i] += o.q[i];
  }
  // The point nearest `mean` among those that minimise the summed squared plane distances: directions in
  // which the planes do not constrain the point (along a flat wall, along the edge of two walls) keep the
  // corners' mean, as vtkQuadricClustering does with its truncated pseudo-inverse.
  Vec3 solve(const Vec3& mean) const {
    Eigen::Matrix3d a;
    a << q[0], q[1], q[2], q[1], q[3], q[4], q[2], q[4], q[5];
    const Vec3 b(q[6], q[7], q[8]);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(a);
    const Eigen::Vector3d lambda = eigen.eigenvalues();
    const double largest = lambda.cwiseAbs().maxCoeff();
    if (!(largest > 0)) return mean;
    Eigen::Vector3d inverse = Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i)
      if (std::abs(lambda[i]) > 1e-3 * largest) inverse[i] = 1.0 / lambda[i];
    const Eigen::Matrix3d& v = eigen.eigenvectors();
    return mean + v * inverse.asDiagonal() * v.transpose() * (b - a * mean);
  }
};

}  // namespace

std::size_t triangleCount(const Mesh& mesh) {
  std::size_t triangles = 0;
  for (const Element& element : mesh.elements)
    triangles += element.vertices.size() >= 3 ? element.vertices.size() - 2 : 0;
  return triangles;
}

bool wantsStandIn(const Mesh& mesh) {
  return triangleCount(mesh) > kStandInAboveTriangles;
}

StandInMesh::StandInMesh(const Mesh& mesh, std::size_t targetTriangles) {
  // A plane crossing a grid of bins of side s occupies about area / s^2 of them, and clustering a fine
  // mesh leaves about two triangles per occupied bin: s = sqrt(2 area / target). One correction after the
  // first try covers scenes whose surfaces are not mostly axis-aligned planes.
  double area = 0;
  for (const Element& element : mesh.elements) area += element.area;
  const double target = static_cast<double>(std::max<std::size_t>(targetTriangles, 100));
  double size = std::sqrt(2.0 * std::max(area, 1e-12) / target);
  build(mesh, size);
  const double ratio = static_cast<double>(triangleCount()) / target;
  if (ratio > 1.3 || (ratio < 0.6 && triangleCount() < 3 * ::rt::viz::triangleCount(mesh) / 4)) {
    size *= std::sqrt(ratio);
    build(mesh, size);
  }
}

void StandInMesh::build(const Mesh& mesh, double binSize) {
  binSize_ = binSize;
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::max()), high = -low;
  for (const Vec3& p : mesh.vertices) low = low.cwiseMin(p), high = high.cwiseMax(p);
  // Walls often lie at round coordinates: an odd offset keeps them off the bins' faces.
  const Vec3 origin = low - Vec3::Constant(0.37 * binSize);
  std::array<std::uint64_t, 3> dims{};
  for (int a = 0; a < 3; ++a)
    dims[static_cast<std::size_t>(a)] =
        static_cast<std::uint64_t>(std::max(0.0, (high[a] - origin[a]) / binSize)) + 1;
  std::vector<std::uint64_t> binOfVertex(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3 cell = (mesh.vertices[v] - origin) / binSize;
    std::array<std::uint64_t, 3> i{};
    for (int a = 0; a < 3; ++a)
      i[static_cast<std::size_t>(a)] =
          std::min(static_cast<std::uint64_t>(std::max(0.0, cell[a])), dims[static_cast<std::size_t>(a)] - 1);
    binOfVertex[v] = (i[2] * dims[1] + i[1]) * dims[0] + i[0];
  }

  // Clusters: (bin, facing) pairs in the order their first corner comes.
  std::unordered_map<std::uint64_t, std::int32_t> clusterOf;
  std::vector<std::uint64_t> keys;
  std::vector<Vec3> sums;
  std::vector<Quadric> quadrics;
  clusterOfCorner_.clear();
  clusterCorners_.clear();
  std::uint64_t lastKey = ~std::uint64_t{0};
  std::int32_t lastCluster = -1;
  for (const Element& element : mesh.elements) {
    const std::uint64_t face = facing(element.normal);
    const double d = element.normal.dot(element.centroid);
    const std::size_t first = clusterOfCorner_.size();
    for (int v : element.vertices) {
      // Neighbouring elements come one after the other: most corners fall in the previous corner's cluster.
      const std::uint64_t key = binOfVertex[static_cast<std::size_t>(v)] << 3 | face;
      if (key != lastKey) {
        auto [it, fresh] = clusterOf.try_emplace(key, static_cast<std::int32_t>(keys.size()));
        if (fresh) {
          keys.push_back(key);
          sums.emplace_back(Vec3::Zero());
          quadrics.emplace_back();
          clusterCorners_.push_back(0);
        }
        lastKey = key;
        lastCluster = it->second;
      }
      const auto c = static_cast<std::size_t>(lastCluster);
      sums[c] += mesh.vertices[static_cast<std::size_t>(v)];
      ++clusterCorners_[c];
      // An element's plane counts once in each cluster it touches, weighted by its area.
      if (std::find(clusterOfCorner_.begin() + static_cast<std::ptrdiff_t>(first), clusterOfCorner_.end(),
                    lastCluster) == clusterOfCorner_.end())
        quadrics[c].add(element.normal, d, element.area);
      clusterOfCorner_.push_back(lastCluster);
    }
  }

  // One point per bin, shared by its facings: the faces of a wall and the floor it stands on meet without a
  // gap. Clusters sorted by key lie bin by bin.
  std::vector<std::int32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return keys[static_cast<std::size_t>(a)] < keys[static_cast<std::size_t>(b)];
  });
  positions_.assign(3 * keys.size(), 0.0f);
  for (std::size_t begin = 0; begin < order.size();) {
    const std::uint64_t bin = keys[static_cast<std::size_t>(order[begin])] >> 3;
    std::size_t end = begin;
    Quadric quadric;
    Vec3 sum = Vec3::Zero();
    double count = 0;
    for (; end < order.size() && keys[static_cast<std::size_t>(order[end])] >> 3 == bin; ++end) {
      const auto c = static_cast<std::size_t>(order[end]);
      quadric.add(quadrics[c]);
      sum += sums[c];
      count += clusterCorners_[c];
    }
    const Vec3 binLow = origin + binSize * Vec3(static_cast<double>(bin % dims[0]),
                                                static_cast<double>(bin / dims[0] % dims[1]),
                                                static_cast<double>(bin / dims[0] / dims[1]));
    // The planes' meeting point can lie outside the bin when they are nearly parallel: kept inside.
    const Vec3 point = quadric.solve(sum / count).cwiseMax(binLow).cwiseMin(binLow + Vec3::Constant(binSize));
    for (std::size_t k = begin; k < end; ++k)
      for (int a = 0; a < 3; ++a)
        positions_[3 * static_cast<std::size_t>(order[k]) + static_cast<std::size_t>(a)] =
            static_cast<float>(point[a]);
    begin = end;
  }

  // Each element fanned into triangles over its corners' clusters; those with three different clusters
  // stay, once each (rotated so the smallest id leads, which keeps the winding).
  if (keys.size() >= (std::size_t{1} << kClusterBits))
    throw std::length_error("stand-in with " + std::to_string(keys.size()) + " clusters");
  std::vector<std::uint64_t> packed;
  std::size_t corner = 0;
  for (const Element& element : mesh.elements) {
    const std::int32_t* c = clusterOfCorner_.data() + corner;
    corner += element.vertices.size();
    for (std::size_t k = 1; k + 1 < element.vertices.size(); ++k) {
      std::array<std::uint64_t, 3> t{static_cast<std::uint64_t>(c[0]), static_cast<std::uint64_t>(c[k]),
                                     static_cast<std::uint64_t>(c[k + 1])};
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      packed.push_back(t[0] << (2 * kClusterBits) | t[1] << kClusterBits | t[2]);
    }
  }
  std::sort(packed.begin(), packed.end());
  packed.erase(std::unique(packed.begin(), packed.end()), packed.end());
  constexpr std::uint64_t mask = (std::uint64_t{1} << kClusterBits) - 1;
  triangles_.clear();
  triangles_.reserve(3 * packed.size());
  for (std::uint64_t t : packed)
    for (int shift : {2 * kClusterBits, kClusterBits, 0})
      triangles_.push_back(static_cast<std::int32_t>(t >> shift & mask));
}

vtkSmartPointer<vtkPolyData> StandInMesh::makePolyData(const ScenePaint& paint) const {
  auto coordinates = vtkSmartPointer<vtkFloatArray>::New();
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(clusterCount()));
  std::copy(positions_.begin(), positions_.end(), coordinates->GetPointer(0));
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(coordinates);

  auto offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
  offsets->SetNumberOfValues(static_cast<vtkIdType>(triangleCount()) + 1);
  for (vtkIdType t = 0; t <= static_cast<vtkIdType>(triangleCount()); ++t)
    offsets->SetValue(t, static_cast<std::int32_t>(3 * t));
  auto connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(triangles_.size()));
  std::copy(triangles_.begin(), triangles_.end(), connectivity->GetPointer(0));
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  triangles->SetData(offsets, connectivity);

  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetName("colour");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(static_cast<vtkIdType>(clusterCount()));

  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(triangles);
  data->GetPointData()->SetScalars(colours);
  recolour(*data, paint);
  return data;
}

void StandInMesh::recolour(vtkPolyData& data, const ScenePaint& paint) const {
  auto* colours = vtkUnsignedCharArray::SafeDownCast(data.GetPointData()->GetArray("colour"));
  if (!colours || colours->GetNumberOfTuples() != static_cast<vtkIdType>(clusterCount()))
    throw std::invalid_argument("the polydata is not this stand-in's");
  std::uint8_t* bytes = colours->GetPointer(0);
  if (paint.firstCorner.empty()) {
    std::fill(bytes, bytes + 3 * clusterCount(), kUnpainted);
  } else {
    if (paint.colours.size() != cornerCount())
      throw std::invalid_argument("the paint has " + std::to_string(paint.colours.size()) + " corners for " +
                                  std::to_string(cornerCount()));
    // The mean of the corners' 8-bit colours: the stand-in is seen only while it moves, where the
    // difference to a mean of linear light does not show.
    std::vector<std::uint32_t> sums(3 * clusterCount(), 0);
    for (std::size_t k = 0; k < clusterOfCorner_.size(); ++k) {
      std::uint32_t* sum = sums.data() + 3 * static_cast<std::size_t>(clusterOfCorner_[k]);
      const Rgb8& colour = paint.colours[k];
      sum[0] += colour[0], sum[1] += colour[1], sum[2] += colour[2];
    }
    for (std::size_t c = 0; c < clusterCount(); ++c) {
      const auto n = static_cast<std::uint32_t>(clusterCorners_[c]);
      for (std::size_t i = 0; i < 3; ++i)
        bytes[3 * c + i] = static_cast<std::uint8_t>((sums[3 * c + i] + n / 2) / n);
    }
  }
  colours->Modified();
}

}  // namespace rt::viz
