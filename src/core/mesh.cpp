#include "core/mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "core/check.h"
#include "core/contact_lines.h"
#include "core/io/scene_assembly.h"
#include "core/memory_budget.h"
#include "core/polygon.h"

namespace rt {
namespace {

// Merges coincident vertices (within a tolerance relative to the scene size) so that elements of the same
// patch and of abutting patches share them.
class VertexWelder {
 public:
  VertexWelder(std::vector<Vec3>& vertices, double cell) : vertices_(vertices), cell_(cell) {}

  int add(const Vec3& p) {
    const auto key = keyOf(p);
    // Look in the neighbouring cells too, so points straddling a cell border still merge.
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find({std::get<0>(key) + dx, std::get<1>(key) + dy, std::get<2>(key) + dz});
          if (it == cells_.end()) continue;
          for (int index : it->second)
            if ((vertices_[index] - p).norm() <= cell_) return index;
        }
    const int index = static_cast<int>(vertices_.size());
    vertices_.push_back(p);
    cells_[key].push_back(index);
    return index;
  }

 private:
  using Key = std::tuple<long long, long long, long long>;
  Key keyOf(const Vec3& p) const {
    return {static_cast<long long>(std::floor(p.x() / cell_)),
            static_cast<long long>(std::floor(p.y() / cell_)),
            static_cast<long long>(std::floor(p.z() / cell_))};
  }
  std::vector<Vec3>& vertices_;
  double cell_;
  std::map<Key, std::vector<int>> cells_;
};

double sceneSize(const Scene& scene) {
  return scene.bounds().isEmpty() ? 1.0 : scene.bounds().diagonal().norm();
}

bool cuts(const MeshOptions& options) {
  return options.splitAtContacts && options.mode != MeshOptions::Mode::None;
}

// Divisions per edge, in double: an absurd request (a micrometre edge on a room) must be countable before it
// is refused, not overflow an int.
double divisionsFor(const Polygon& polygon, const MeshOptions& options) {
  switch (options.mode) {
    case MeshOptions::Mode::None:
      return 1;
    case MeshOptions::Mode::Count:
      return options.count;
    case MeshOptions::Mode::MaxEdge:
      return std::max(1.0, std::ceil(maxEdgeLength(polygon) / options.maxEdge - 1e-9));
  }
  return 1;
}

// One element per patch keeps convex polygons whole up to this many vertices (the samplers of the
// form-factor methods take up to 16); larger ones become a fan of triangles.
constexpr std::size_t kMaxElementVertices = 8;

bool keptWhole(const Polygon& polygon, const MeshOptions& options) {
  return polygon.size() <= 4 ||
         (options.mode == MeshOptions::Mode::None && polygon.size() <= kMaxElementVertices);
}

// Elements buildMesh will make for one patch (quads and triangles split n x n, larger polygons by fan).
double elementCount(const Polygon& polygon, const MeshOptions& options) {
  if (keptWhole(polygon, options)) {
    const double n = divisionsFor(polygon, options);
    return n * n;
  }
  double count = 0;
  for (const Polygon& t : fanTriangulate(polygon)) {
    const double n = divisionsFor(t, options);
    count += n * n;
  }
  return count;
}

// Bytes per element of a finished mesh: the element (vertex indices, normal, centroid), about one welded
// vertex with its lookup entry and element list, and the copied material rows. Measured order of magnitude.
constexpr double kBytesPerElement = 400;

// Refuses, before any allocation, a mesh that cannot fit in memory, with the numbers and what to do instead.
void checkMeshSize(const Scene& scene, const MeshOptions& options) {
  const double elements = estimatedElementCount(scene, options);
  const double bytes = elements * kBytesPerElement, budget = memoryBudgetBytes();
  // Element and vertex indices are ints.
  const double indexLimit = static_cast<double>(std::numeric_limits<int>::max()) / 8;
  if (bytes <= budget && elements <= indexLimit) return;
  const std::string option = options.mode == MeshOptions::Mode::Count
                                 ? "--subdivide " + std::to_string(options.count)
                                 : "--max-edge " + io_detail::formatNumber(options.maxEdge);
  // Elements grow as 1 / edge^2: the edge (or count) that gives about 10,000 elements.
  const double shrink = std::sqrt(elements / 1e4);
  const std::string suggestion =
      options.mode == MeshOptions::Mode::Count
          ? "--subdivide " + std::to_string(std::max(1, static_cast<int>(options.count / shrink)))
          : "--max-edge " + io_detail::formatNumber(options.maxEdge * shrink);
  throw InputError({scene.sourceFile},
                   option + " would make about " + formatCount(elements) + " elements, needing about " +
                       formatBytes(bytes) + " for the mesh alone (a dense form-factor matrix: " +
                       formatBytes(8 * elements * elements) + "); this machine has " + formatBytes(budget) +
                       ". Use a coarser mesh, e.g. " + suggestion + " (about 10,000 elements) in " +
                       scene.unit + ", or --mesh adaptive");
}

// Bilinear N x N split of a convex quad: the sub-quads of a planar convex quad are planar and convex.
void splitQuad(const Polygon& q, int n, std::vector<Polygon>& out) {
  auto at = [&](int i, int j) {
    const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
    return Vec3((1 - u) * (1 - v) * q[0] + u * (1 - v) * q[1] + u * v * q[2] + (1 - u) * v * q[3]);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) out.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
}

// Barycentric split of a triangle into n^2 similar triangles.
void splitTriangle(const Polygon& t, int n, std::vector<Polygon>& out) {
  auto at = [&](int i, int j) {  // i along edge 0->1, j along edge 0->2
    return Vec3(t[0] + (t[1] - t[0]) * (static_cast<double>(i) / n) +
                (t[2] - t[0]) * (static_cast<double>(j) / n));
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i + j < n; ++i) {
      out.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + j + 1 < n) out.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
}

// Vertices closer than this become one: 1e-9 of the scene, but not more than 1e-8 of the shortest element
// edge, since welding moves a vertex by up to this much. A scene with one far-away polygon (a coordinate of
// 1e10 among millimetres) would otherwise weld the corners of its small elements together.
double weldTolerance(const Scene& scene, const MeshOptions& options, double sceneSize) {
  double shortest = sceneSize, largest = 0;
  for (const Patch& patch : scene.patches) {
    for (const Vec3& v : patch.vertices) largest = std::max(largest, v.cwiseAbs().maxCoeff());
    const double n = divisionsFor(patch.vertices, options);
    for (std::size_t k = 0; k < patch.vertices.size(); ++k)
      shortest = std::min(shortest,
                          (patch.vertices[(k + 1) % patch.vertices.size()] - patch.vertices[k]).norm() / n);
  }
  // Not below 1e-15 of the largest coordinate: the welder's grid keys (coordinate / tolerance) fit in 64
  // bits, and double rounding of shared corners stays inside.
  return std::max(std::min(1e-9 * sceneSize, 1e-8 * shortest), 1e-15 * largest);
}

// The contract every form-factor method relies on: elements are planar convex polygons of 3 to 8 vertices
// with positive area, facing their patch's way. Subdividing valid patches keeps it; a violation is a bug.
// Planarity is only owed where the patch was planar: scenes built in code (tests of twisted occluders) may
// hand in a non-planar quad, which the loaders would have split.
void checkElements(const Mesh& mesh, const Scene& scene) {
  if (!checksEnabled()) return;
  std::vector<char> planarPatch(scene.patches.size());
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    const Polygon& v = scene.patches[i].vertices;
    planarPatch[i] = planarityDeviation(v) <= 1e-6 * maxEdgeLength(v);
  }
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& element = mesh.elements[e];
    const std::string who = "element " + std::to_string(e) + " of patch " + std::to_string(element.patch);
    RT_CHECK(element.vertices.size() >= 3 && element.vertices.size() <= kMaxElementVertices,
             who + " has " + std::to_string(element.vertices.size()) + " vertices");
    Polygon p;
    for (int v : element.vertices) p.push_back(mesh.vertices[v]);
    const double size = maxEdgeLength(p);
    RT_CHECK(element.area > 0 && std::isfinite(element.area), who + " has no area");
    RT_CHECK(!planarPatch[element.patch] || planarityDeviation(p) <= 1e-6 * size, who + " is not planar");
    RT_CHECK(isConvex(p, element.normal), who + " is not convex about its normal");
  }
}

}  // namespace

Polygon Mesh::polygon(int element) const {
  Polygon p;
  for (int v : elements[element].vertices) p.push_back(vertices[v]);
  return p;
}

Eigen::VectorXd Mesh::areas() const {
  Eigen::VectorXd a(static_cast<Eigen::Index>(elements.size()));
  for (std::size_t i = 0; i < elements.size(); ++i) a[static_cast<Eigen::Index>(i)] = elements[i].area;
  return a;
}

std::vector<int> Mesh::edgeNeighbours(int element) const {
  std::vector<int> result;
  const auto& vs = elements[element].vertices;
  for (std::size_t k = 0; k < vs.size(); ++k) {
    const int a = vs[k], b = vs[(k + 1) % vs.size()];
    for (int other : vertexElements[a]) {
      if (other == element) continue;
      const auto& ov = elements[other].vertices;
      if (std::find(ov.begin(), ov.end(), b) != ov.end() &&
          std::find(result.begin(), result.end(), other) == result.end())
        result.push_back(other);
    }
  }
  return result;
}

std::uint64_t Mesh::geometryHash() const {
  // FNV-1a over the raw coordinates and the element connectivity.
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
  };
  for (const Vec3& v : vertices) mix(v.data(), sizeof(double) * 3);
  for (const Element& e : elements) {
    mix(e.vertices.data(), e.vertices.size() * sizeof(int));
    const int separator = -1;
    mix(&separator, sizeof separator);
  }
  return h;
}

Mesh buildMesh(const Scene& scene, const MeshOptions& options) {
  if (options.mode == MeshOptions::Mode::Count && options.count < 1)
    throw InputError({}, "--subdivide needs a count of at least 1, got " + std::to_string(options.count));
  if (options.mode == MeshOptions::Mode::MaxEdge &&
      !(options.maxEdge > 0.0 && std::isfinite(options.maxEdge)))
    throw InputError({}, "--max-edge needs a positive length");

  checkMeshSize(scene, options);

  Mesh mesh;
  const double size = std::max(sceneSize(scene), 1e-300);
  VertexWelder welder(mesh.vertices, weldTolerance(scene, options, size));

  std::vector<Polygon> pieces;
  for (std::size_t p = 0; p < scene.patches.size(); ++p) {
    const Patch& patch = scene.patches[p];
    pieces.clear();
    const std::vector<Polygon> parts =
        cuts(options) ? cutAtContacts(scene, static_cast<int>(p), 1e-7 * size, options.overlapGap * size)
                      : std::vector<Polygon>{patch.vertices};
    for (const Polygon& part : parts) {
      const int n = static_cast<int>(divisionsFor(part, options));
      if (part.size() == 4) {
        splitQuad(part, n, pieces);
      } else if (part.size() == 3) {
        splitTriangle(part, n, pieces);
      } else if (keptWhole(part, options)) {
        pieces.push_back(part);  // a convex n-gon, one element as asked
      } else {
        for (const Polygon& t : fanTriangulate(part))
          splitTriangle(t, static_cast<int>(divisionsFor(t, options)), pieces);
      }
    }
    for (const Polygon& piece : pieces) {
      Element e;
      e.patch = static_cast<int>(p);
      for (const Vec3& v : piece) e.vertices.push_back(welder.add(v));
      e.normal = patch.normal;
      e.area = polygonArea(piece);
      e.centroid = polygonCentroid(piece);
      mesh.elements.push_back(std::move(e));
    }
  }
  checkElements(mesh, scene);
  mesh.vertexElements.assign(mesh.vertices.size(), {});
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    for (int v : mesh.elements[e].vertices) mesh.vertexElements[v].push_back(static_cast<int>(e));
  refreshMaterials(mesh, scene);
  return mesh;
}

void refreshMaterials(Mesh& mesh, const Scene& scene) {
  const auto n = static_cast<Eigen::Index>(mesh.elements.size());
  mesh.reflectance.resize(n, 3);
  mesh.emission.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Material& m = scene.materialOfPatch(mesh.elements[i].patch);
    mesh.reflectance.row(i) = m.reflectance.matrix().transpose();
    mesh.emission.row(i) = m.emission.matrix().transpose();
  }
}

namespace {

// Each patch as the parts the mesh splits: the patch, or its pieces cut at contact lines and overlaps.
std::vector<std::vector<Polygon>> meshedParts(const Scene& scene, const MeshOptions& options) {
  const double size = sceneSize(scene);
  std::vector<std::vector<Polygon>> parts;
  parts.reserve(scene.patches.size());
  for (std::size_t p = 0; p < scene.patches.size(); ++p)
    parts.push_back(cuts(options)
                        ? cutAtContacts(scene, static_cast<int>(p), 1e-7 * size, options.overlapGap * size)
                        : std::vector<Polygon>{scene.patches[p].vertices});
  return parts;
}

double countElements(const std::vector<std::vector<Polygon>>& parts, const MeshOptions& options) {
  double elements = 0;
  for (const auto& patch : parts)
    for (const Polygon& part : patch) elements += elementCount(part, options);
  return elements;
}

}  // namespace

double estimatedElementCount(const Scene& scene, const MeshOptions& options) {
  return countElements(meshedParts(scene, options), options);
}

std::vector<MeshCut> meshCuts(const Scene& scene, const MeshOptions& options) {
  std::vector<MeshCut> out;
  if (!cuts(options)) return out;
  const double size = sceneSize(scene);
  for (std::size_t p = 0; p < scene.patches.size(); ++p) {
    const std::size_t first = out.size();
    for (const CutSegment& s :
         cutSegments(scene, static_cast<int>(p), 1e-7 * size, options.overlapGap * size)) {
      const int surface = scene.patches[static_cast<std::size_t>(s.other)].surface;
      auto it =
          std::find_if(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
                       [&](const MeshCut& c) { return c.surface == surface && c.overlap == s.overlap; });
      if (it == out.end()) it = out.insert(out.end(), MeshCut{static_cast<int>(p), surface, s.overlap, 0, 0});
      it->gap = std::max(it->gap, s.gap);
      ++it->segments;
    }
  }
  return out;
}

std::vector<std::string> describeMeshCuts(const Scene& scene, const std::vector<MeshCut>& cuts) {
  std::vector<std::string> lines;
  for (const MeshCut& c : cuts) {
    const Patch& patch = scene.patches[static_cast<std::size_t>(c.patch)];
    const std::string& cut = scene.surfaces[static_cast<std::size_t>(patch.surface)].name;
    const std::string& by = scene.surfaces[static_cast<std::size_t>(c.surface)].name;
    const std::string segments = std::to_string(c.segments) + (c.segments == 1 ? " segment" : " segments");
    lines.push_back(cut + " (patch " + std::to_string(c.patch) + ") " +
                    (c.overlap ? "along the outline of " + by + ", " + io_detail::formatNumber(c.gap, 3) +
                                     " " + scene.unit + " in front of it (overlap): "
                               : "where " + by + " stands on it (contact): ") +
                    segments);
  }
  return lines;
}

MeshOptions defaultMeshOptions(const Scene& scene, double elements) {
  if (static_cast<double>(scene.patches.size()) >= elements) return {};
  double longest = 0;
  for (const Patch& patch : scene.patches) longest = std::max(longest, maxEdgeLength(patch.vertices));
  MeshOptions options;
  options.mode = MeshOptions::Mode::MaxEdge;
  options.splitAtContacts = true;
  const auto parts = meshedParts(scene, options);
  // The count only grows as the edge shrinks: bisect on the edge (in log scale) for the largest edge that
  // still gives `elements`, then round it down to two significant digits, which a reader can retype.
  double coarse = longest, fine = longest / std::sqrt(elements) / 4;
  for (int k = 0; k < 60; ++k) {
    options.maxEdge = std::sqrt(coarse * fine);
    (countElements(parts, options) >= elements ? fine : coarse) = options.maxEdge;
  }
  const double scale = std::pow(10.0, std::floor(std::log10(fine)) - 1);
  options.maxEdge = std::floor(fine / scale) * scale;
  return options;
}

}  // namespace rt
