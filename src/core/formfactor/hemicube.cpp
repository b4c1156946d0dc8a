#include "core/formfactor/hemicube.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>

#include "core/geometry/plane_clip.h"

namespace rt {
namespace {

// The four side planes of a face's frustum, widened by `margin` as the clipping below widens it, with the
// lengths of their normals: made once per face, not once per element and face.
struct FrustumPlanes {
  double w = 0, low = 0, wideNorm = 0, lowNorm = 0;
};
FrustumPlanes frustumPlanes(const HemicubeFaceAxes& face, double margin) {
  const double w = 1 + margin, low = face.upMin - margin;
  return {w, low, std::sqrt(1 + w * w), std::sqrt(1 + low * low)};
}

// A point of the eye's frame in a face's coordinates (p . across, p . up, p . forward with the axes of
// hemicubeFaceAxes below, face by face): those axes are the frame's axes and their opposites, so a
// permutation with signs, exact, instead of three dot products.
inline Vec3 toFace(int face, const Vec3& p) {
  switch (face) {
    case 0:
      return p;
    case 1:
      return {p.y(), p.z(), p.x()};
    case 2:
      return {-p.x(), p.z(), p.y()};
    case 3:
      return {-p.y(), p.z(), -p.x()};
    default:
      return {p.x(), p.z(), -p.y()};
  }
}

// True when the sphere lies entirely outside one of the four side planes of the face's frustum (so the test
// only ever skips what the outcodes would reject).
bool sphereOutsideFrustum(const Vec3& centreOnFace, double radius, const FrustumPlanes& planes) {
  const double x = centreOnFace.x(), y = centreOnFace.y(), z = centreOnFace.z();
  const double w = planes.w, low = planes.low, wideNorm = planes.wideNorm, lowNorm = planes.lowNorm;
  return x - w * z > radius * wideNorm || -x - w * z > radius * wideNorm || y - w * z > radius * wideNorm ||
         low * z - y > radius * lowNorm;
}

// ---- The stages of one hemicube: the eye's frame, then per element its corners in that frame and a bounding
// sphere, per face the polygon clipped to the face's frustum, and its scan conversion into the z-buffer.

constexpr double kFrustumMargin = 1e-3;  // the frustum's widening: pixel centres lie half a pixel inside

// Another element as the eye sees it: its corners in the eye's frame, a bounding sphere, its plane.
struct ElementInEye {
  std::array<Vec3, 8> local;
  int count = 0;
  Vec3 centre;
  double radius = 0;
  Vec3 m;  // the plane m . p = c, in the eye's frame
  double c = 0;
  int id = kHemicubeSeesNothing;  // the element, or kHemicubeSeesBackFace when it turns its back to the eye
};

// False when element j covers no pixel: edge-on to the eye or entirely below its horizon.
bool elementInEye(const HemicubeMesh& mesh, int j, const HemicubeFaces& eye,
                  const std::vector<Vec3>& localVertices, double near, double eyeEps, ElementInEye& out) {
  const HemicubeMesh::Record& other = mesh.elements[j];
  const Vec3& anchor = mesh.mesh.vertices[other.vertices[0]];
  const double facing = other.normal.dot(eye.origin - anchor);
  if (std::abs(facing) <= eyeEps) return false;  // edge-on: covers no pixel centre
  out.id = facing > 0 ? j : kHemicubeSeesBackFace;
  // A bounding sphere in the eye's frame rejects most (element, face) combinations with a few comparisons
  // before the per-vertex outcodes: a small element lies on one or two of the five faces. Made once per mesh
  // and moved into the eye's frame; widened by a relative 1e-9 and by `near` (1e-9 of the scene), far more
  // than the rounding of either frame, so that it only ever skips what the corners' own tests would.
  const Vec3 d = other.centre - eye.origin;
  out.centre = Vec3(d.dot(eye.u), d.dot(eye.v), d.dot(eye.normal));
  out.radius = other.radius * (1 + 1e-9) + near;
  if (out.centre.z() + out.radius < near) return false;  // wholly below the horizon
  out.count = other.count;
  bool above = false;
  for (int k = 0; k < out.count; ++k) {
    out.local[k] = localVertices[other.vertices[k]];
    above |= out.local[k].z() > near;
  }
  if (!above) return false;
  out.m = Vec3(other.normal.dot(eye.u), other.normal.dot(eye.v), other.normal.dot(eye.normal));
  out.c = out.m.dot(out.local[0]);
  return true;
}

// The element's polygon in face f's coordinates (across, up, depth), clipped to the face's frustum (slightly
// widened: pixel centres lie at least half a pixel inside), so that projected coordinates stay bounded: the
// near plane alone would leave points at depth ~0 projecting to ~1e9 pixels, where edge functions lose all
// precision. Returns the number of corners in `clipped` (below 3: nothing to draw).
int clipToFace(const ElementInEye& e, int f, const HemicubeFaceAxes& face, double near,
               std::array<Vec3, 16>& clipped) {
  constexpr double margin = kFrustumMargin;
  // Outcodes against the five frustum planes: reject when all vertices are outside one of them, skip
  // clipping when all are inside every one (the common cases: then the corners go straight to `clipped`).
  unsigned allOutside = 31, anyOutside = 0;
  for (int k = 0; k < e.count; ++k) {
    const Vec3 p = toFace(f, e.local[k]);
    clipped[k] = p;
    const double w = (1 + margin) * p.z();
    const unsigned code = (p.z() < near ? 1u : 0u) | (p.x() > w ? 2u : 0u) | (p.x() < -w ? 4u : 0u) |
                          (p.y() > w ? 8u : 0u) | (p.y() < (face.upMin - margin) * p.z() ? 16u : 0u);
    allOutside &= code;
    anyOutside |= code;
  }
  if (allOutside != 0) return 0;
  int n = e.count;
  if (anyOutside == 0) return n;
  std::array<Vec3, 16> in;
  for (int k = 0; k < n; ++k) in[k] = clipped[k];
  auto clipBy = [&](auto distance) {
    if (n < 3) return;
    std::array<double, 16> heights;
    bool cut = false;
    for (int k = 0; k < n; ++k) heights[k] = distance(in[k]), cut |= heights[k] < 0;
    if (!cut) return;  // every corner kept, in order: the cut would only copy the polygon
    int m = 0;
    cutByHeights(
        in.data(), heights.data(), n, [&](const Vec3& p) { clipped[m++] = p; }, [](const Vec3&) {});
    n = m;
    for (int k = 0; k < n; ++k) in[k] = clipped[k];
  };
  clipBy([&](const Vec3& p) { return p.z() - near; });
  clipBy([&](const Vec3& p) { return (1 + margin) * p.z() - p.x(); });
  clipBy([&](const Vec3& p) { return (1 + margin) * p.z() + p.x(); });
  clipBy([&](const Vec3& p) { return (1 + margin) * p.z() - p.y(); });
  clipBy([&](const Vec3& p) { return p.y() - (face.upMin - margin) * p.z(); });
  return n;
}

// Scan conversion of a clipped polygon into face f's z-buffer: pixel centres inside every edge, nearest
// (largest inverse depth) wins.
void drawPolygon(const std::array<Vec3, 16>& clipped, int n, const ElementInEye& e,
                 const HemicubeFaceAxes& face, HemicubeFaceBuffer& buffer, std::vector<double>& zbuffer) {
  const Vec3& m = e.m;
  const double c = e.c;
  const int id = e.id;
  // Project to pixel units: x in [0, width), y in [0, height).
  std::array<Vec2, 16> screen;
  const double sx = buffer.width / 2.0, sy = buffer.height / (1.0 - face.upMin);
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (int k = 0; k < n; ++k) {
    const double x = (clipped[k].x() / clipped[k].z() + 1.0) * sx;
    const double y = (clipped[k].y() / clipped[k].z() - face.upMin) * sy;
    screen[k] = Vec2(x, y);
    xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
  }
  const int c0 = std::max(0, static_cast<int>(std::ceil(xmin - 0.5)));
  const int c1 = std::min(buffer.width - 1, static_cast<int>(std::floor(xmax - 0.5)));
  int r0 = std::max(0, static_cast<int>(std::ceil(ymin - 0.5)));
  int r1 = std::min(buffer.height - 1, static_cast<int>(std::floor(ymax - 0.5)));
  if (c0 > c1 || r0 > r1) return;
  // Plane in face coordinates: m_face . (X, Y, 1) * depth = c, so 1/depth = (m_face . (X, Y, 1)) / c with
  // X = x / sx - 1, Y = y / sy + upMin.
  const Vec3 mf(m.dot(face.across), m.dot(face.up), m.dot(face.forward));
  if (c == 0) return;
  // A back face is pushed a hair farther (1e-7 of its depth): where it coincides with a front face, as
  // in an occluder modelled as two back-to-back polygons, the front face must win the depth test instead
  // of the two taking pixels at random by rounding.
  const double push = id == kHemicubeSeesBackFace ? 1 - 1e-7 : 1.0;
  const double kx = push * mf.x() / (c * sx), ky = push * mf.y() / (c * sy);
  const double k0 = push * (mf.z() - mf.x() + mf.y() * face.upMin) / c;
  // Orientation of the projected polygon, so that inside means all edge functions >= 0.
  double area2 = 0;
  for (int k = 0; k < n; ++k) {
    const Vec2& p = screen[k];
    const Vec2& q = screen[k + 1 < n ? k + 1 : 0];
    area2 += p.x() * q.y() - q.x() * p.y();
  }
  if (area2 == 0) return;
  const double orientation = area2 > 0 ? 1.0 : -1.0;
  // Edge functions e(x, y) = a x + b y + c, inside where e >= 0, sorted once by what they bound along a row:
  // a > 0 the span's left end, a < 0 its right end, a = 0 (horizontal) whether the row is inside at all. A
  // row's span is then a pass over each list without a branch per edge.
  struct Edge {
    double a, b, c, inverseA;
  };
  std::array<Edge, 16> lefts, rights, flats;
  int leftCount = 0, rightCount = 0, flatCount = 0;
  for (int k = 0; k < n; ++k) {
    const Vec2& p = screen[k];
    const Vec2& q = screen[k + 1 < n ? k + 1 : 0];
    Edge edge;
    edge.a = -(q.y() - p.y()) * orientation;
    edge.b = (q.x() - p.x()) * orientation;
    edge.c = -(edge.a * p.x() + edge.b * p.y());
    // Clipping through a frustum corner can leave two vertices a rounding error apart: such an edge has
    // no direction, and its half-plane (-rest / a with a ~ 1e-17) would empty whole rows at random.
    if ((q - p).squaredNorm() < 1e-18) edge.a = edge.b = edge.c = 0.0;
    edge.inverseA = edge.a != 0 ? 1.0 / edge.a : 0.0;  // one division per edge, not per edge and row
    if (edge.a > 0)
      lefts[leftCount++] = edge;
    else if (edge.a < 0)
      rights[rightCount++] = edge;
    else
      flats[flatCount++] = edge;
  }
  // A horizontal edge leaves out the rows on one side of it, so the rows inside all of them are one run:
  // found from its two ends, with the test every row would make.
  auto outsideAFlat = [&](int row) {
    const double y = row + 0.5;
    bool outside = false;
    for (int k = 0; k < flatCount; ++k) outside |= flats[k].b * y + flats[k].c < -1e-9;
    return outside;
  };
  if (flatCount > 0) {
    while (r0 <= r1 && outsideAFlat(r0)) ++r0;
    while (r1 >= r0 && outsideAFlat(r1)) --r1;
  }
  // The rows, with the number of edges on each side known to the compiler for the common shapes (one or
  // two a side: triangles and quads) so that a row's span is straight-line code.
  auto scan = [&]<int knownLefts, int knownRights>() {
    const int lc = knownLefts > 0 ? knownLefts : leftCount, rc = knownRights > 0 ? knownRights : rightCount;
    for (int row = r0; row <= r1; ++row) {
      const double y = row + 0.5;
      // Span of the row: intersect the half-planes along x.
      double lo = c0 + 0.5, hi = c1 + 0.5;
      for (int k = 0; k < lc; ++k) lo = std::max(lo, -(lefts[k].b * y + lefts[k].c) * lefts[k].inverseA);
      for (int k = 0; k < rc; ++k) hi = std::min(hi, -(rights[k].b * y + rights[k].c) * rights[k].inverseA);
      // A pixel centre exactly on an edge shared by two elements must not fall through both (rounding in
      // the divisions above): widen the span by a hair; the z-buffer settles the double coverage.
      lo -= 1e-7, hi += 1e-7;
      const int first = std::max(c0, static_cast<int>(std::ceil(lo - 0.5)));
      const int last = std::min(c1, static_cast<int>(std::floor(hi - 0.5)));
      const std::size_t base = static_cast<std::size_t>(row) * buffer.width;
      const double rowTerm = ky * y + k0;
      double* depths = zbuffer.data() + base;
      int* ids = buffer.element.data() + base;
      // Stepping the inverse depth along the row (one addition per pixel) instead of evaluating the plane
      // at each pixel: over at most a face width of steps the rounding stays near 1e-14 of the depth, far
      // below the 1e-7 that separates a back face from a coincident front face.
      double inverse = kx * (first + 0.5) + rowTerm;
      for (int column = first; column <= last; ++column, inverse += kx) {
        if (inverse > depths[column]) {
          depths[column] = inverse;
          ids[column] = id;
        }
      }
    }
  };
  if (leftCount == 1 && rightCount == 1)
    scan.template operator()<1, 1>();
  else if (leftCount == 2 && rightCount == 1)
    scan.template operator()<2, 1>();
  else if (leftCount == 1 && rightCount == 2)
    scan.template operator()<1, 2>();
  else if (leftCount == 2 && rightCount == 2)
    scan.template operator()<2, 2>();
  else
    scan.template operator()<0, 0>();
}

}  // namespace

HemicubeMesh::HemicubeMesh(const Mesh& m) : mesh(m), elements(m.size()) {
  for (std::size_t j = 0; j < m.size(); ++j) {
    const Element& from = m.elements[j];
    if (from.vertices.size() > std::tuple_size_v<decltype(Record::vertices)>)
      throw std::invalid_argument("hemicube: element " + std::to_string(j) + " has " +
                                  std::to_string(from.vertices.size()) + " corners, at most 8 are drawn");
    Record& to = elements[j];
    to.normal = from.normal;
    to.count = static_cast<int>(from.vertices.size());
    std::copy(from.vertices.begin(), from.vertices.end(), to.vertices.begin());
    to.centre = Vec3::Zero();
    for (int k : from.vertices) to.centre += m.vertices[k];
    to.centre /= to.count;
    double radius = 0;
    for (int k : from.vertices) radius = std::max(radius, (m.vertices[k] - to.centre).squaredNorm());
    to.radius = std::sqrt(radius);
  }
}

HemicubeFaces renderHemicube(const Mesh& mesh, int element, int resolution) {
  HemicubeWorkspace workspace;
  renderHemicube(HemicubeMesh(mesh), element, resolution, workspace);
  return std::move(workspace.faces);
}

void renderHemicube(const HemicubeMesh& hemicubeMesh, int element, int resolution,
                    HemicubeWorkspace& workspace) {
  if (resolution < 2) throw std::invalid_argument("hemicube resolution must be at least 2");
  const Mesh& mesh = hemicubeMesh.mesh;
  const Element& self = mesh.elements[element];
  HemicubeFaces& result = workspace.faces;
  result.resolution = resolution;
  result.element = element;
  result.origin = self.centroid;
  result.normal = self.normal.normalized();
  // Tangent frame from the first edge: any choice is valid, this one aligns the top face with quads.
  const Vec3 edge = mesh.vertices[self.vertices[1]] - mesh.vertices[self.vertices[0]];
  result.u = (edge - edge.dot(result.normal) * result.normal).normalized();
  result.v = result.normal.cross(result.u);

  // Every vertex in the eye's frame, once: elements share their vertices, so this is several times fewer
  // transforms than per element.
  Eigen::AlignedBox3d box;
  std::vector<Vec3>& localVertices = workspace.localVertices;
  localVertices.resize(mesh.vertices.size());
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    const Vec3& p = mesh.vertices[k];
    box.extend(p);
    const Vec3 d = p - result.origin;
    localVertices[k] = Vec3(d.dot(result.u), d.dot(result.v), d.dot(result.normal));
  }
  const double size = box.isEmpty() ? 1.0 : box.diagonal().norm();
  const double near = 1e-9 * size;

  std::array<HemicubeFaceAxes, 5> axes;
  std::array<FrustumPlanes, 5> planes;
  for (int f = 0; f < 5; ++f) {
    const HemicubeFace face = static_cast<HemicubeFace>(f);
    axes[f] = hemicubeFaceAxes(face);
    planes[f] = frustumPlanes(axes[f], kFrustumMargin);
    HemicubeFaceBuffer& buffer = result.faces[f];
    buffer.width = resolution;
    buffer.height = face == HemicubeFace::Top ? resolution : hemicubeSideRows(resolution);
    buffer.element.assign(static_cast<std::size_t>(buffer.width) * buffer.height, kHemicubeSeesNothing);
    if (workspace.computeDepth)
      buffer.depth.assign(buffer.element.size(), std::numeric_limits<float>::infinity());
    else
      buffer.depth.clear();
  }
  // Inverse depths of the z-buffer (larger = nearer): affine in screen space, so no division per pixel.
  auto& inverseDepth = workspace.inverseDepth;
  for (int f = 0; f < 5; ++f) inverseDepth[f].assign(result.faces[f].element.size(), 0.0);

  const double eyeEps = 1e-12 * size;
  ElementInEye other;
  std::array<Vec3, 16> clipped;
  for (int j = 0; j < static_cast<int>(mesh.size()); ++j) {
    if (j == element || !elementInEye(hemicubeMesh, j, result, localVertices, near, eyeEps, other)) continue;
    for (int f = 0; f < 5; ++f) {
      if (sphereOutsideFrustum(toFace(f, other.centre), other.radius, planes[f])) continue;
      const int n = clipToFace(other, f, axes[f], near, clipped);
      if (n >= 3) drawPolygon(clipped, n, other, axes[f], result.faces[f], inverseDepth[f]);
    }
  }
  if (!workspace.computeDepth) return;
  for (int f = 0; f < 5; ++f) {
    HemicubeFaceBuffer& buffer = result.faces[f];
    for (std::size_t p = 0; p < buffer.element.size(); ++p)
      if (buffer.element[p] != kHemicubeSeesNothing)
        buffer.depth[p] = static_cast<float>(1.0 / inverseDepth[f][p]);
  }
}

void accumulateHemicubeRow(const HemicubeFaces& faces, double* row) {
  for (int f = 0; f < 5; ++f) {
    const std::vector<double>& deltas = deltaFormFactors(faces.resolution, static_cast<HemicubeFace>(f));
    const std::vector<int>& ids = faces.faces[f].element;
    for (std::size_t p = 0; p < ids.size(); ++p)
      if (ids[p] >= 0) row[ids[p]] += deltas[p];
  }
}

void hemicubeRow(const HemicubeMesh& mesh, int element, int resolution, HemicubeWorkspace& workspace,
                 double* row) {
  workspace.computeDepth = false;
  renderHemicube(mesh, element, resolution, workspace);
  std::fill(row, row + mesh.elements.size(), 0.0);
  accumulateHemicubeRow(workspace.faces, row);
}

}  // namespace rt
