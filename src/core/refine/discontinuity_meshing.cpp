// Discontinuity meshing: the receivers are triangulated with the shadow boundaries as constrained edges, so
// that elements do not straddle an umbra or penumbra boundary; then one full solve on that mesh.
#include <algorithm>
#include <chrono>

#include "core/polygon.h"
#include "core/refine/constrained_triangulation.h"
#include "core/refine/dense_transfer.h"
#include "core/refine/piece_mesh.h"
#include "core/refine/refine_modes.h"

namespace rt {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// An orthonormal frame in the patch's plane with (u, w, normal) right-handed, so CCW stays CCW in 2D.
struct PlaneFrame {
  Vec3 origin, u, w;
  explicit PlaneFrame(const Patch& patch)
      : origin(patch.vertices[0]),
        u((patch.vertices[1] - patch.vertices[0]).normalized()),
        w(patch.normal.cross(u).normalized()) {}
  Vec2 to2d(const Vec3& p) const { return {(p - origin).dot(u), (p - origin).dot(w)}; }
  Vec3 to3d(const Vec2& p) const { return origin + p.x() * u + p.y() * w; }
};

}  // namespace

RefinedSolution solveDiscontinuity(const Scene& scene, const RefineOptions& options, Progress& progress) {
  const auto start = Clock::now();
  RefinedSolution solution;
  solution.stats.mode = options.mode;
  progress.report(0.0, "critical lines");
  solution.discontinuities = criticalSegments(scene, options.minEdge);
  solution.stats.criticalSegments = solution.discontinuities.size();
  solution.stats.notes = "receivers meshed by " + constrainedTriangulatorName();

  MeshOptions meshOptions;
  meshOptions.mode = MeshOptions::Mode::MaxEdge;
  meshOptions.maxEdge = options.discontinuityMaxEdge;
  const Mesh plain = buildMesh(scene, meshOptions);
  solution.stats.initialElements = plain.size();

  std::vector<std::vector<const CriticalSegment*>> byReceiver(scene.patches.size());
  for (const CriticalSegment& s : solution.discontinuities) byReceiver[s.receiver].push_back(&s);
  const ConstrainedTriangulator triangulate = constrainedTriangulator();
  const Eigen::AlignedBox3d bounds = scene.bounds();
  const double weldScale = 1e-7 * (bounds.isEmpty() ? 1.0 : bounds.diagonal().norm());

  std::vector<Polygon> pieces;
  std::vector<int> patchOf;
  for (std::size_t p = 0; p < scene.patches.size(); ++p) {
    if (progress.cancelled()) throw Cancelled();
    const Patch& patch = scene.patches[p];
    if (byReceiver[p].empty()) {
      for (std::size_t e = 0; e < plain.size(); ++e)
        if (plain.elements[e].patch == static_cast<int>(p)) {
          pieces.push_back(plain.polygon(static_cast<int>(e)));
          patchOf.push_back(static_cast<int>(p));
        }
      continue;
    }
    const PlaneFrame frame(patch);
    PlanarDomain domain;
    for (const Vec3& v : patch.vertices) domain.boundary.push_back(frame.to2d(v));
    for (const CriticalSegment* s : byReceiver[p])
      domain.constraints.push_back({frame.to2d(s->a), frame.to2d(s->b)});
    domain.maxEdge = options.discontinuityMaxEdge;
    const PlanarTriangulation t = triangulate(domain);
    for (const auto& tri : t.triangles) {
      Polygon piece{frame.to3d(t.points[tri[0]]), frame.to3d(t.points[tri[1]]), frame.to3d(t.points[tri[2]])};
      // Slivers from nearly coincident critical lines would weld into degenerate elements: drop them (their
      // area is below any meaningful size).
      const double shortest = std::min(
          {(piece[1] - piece[0]).norm(), (piece[2] - piece[1]).norm(), (piece[0] - piece[2]).norm()});
      if (shortest <= weldScale || polygonArea(piece) <= 1e-9 * patch.area) continue;
      if (newellNormal(piece).dot(patch.normal) < 0) std::swap(piece[1], piece[2]);
      pieces.push_back(std::move(piece));
      patchOf.push_back(static_cast<int>(p));
    }
  }
  Mesh mesh = meshFromPieces(scene, pieces, patchOf);

  const VisibilityOracle visibility(scene);
  TransferOptions transfer;
  transfer.visibilitySamples = options.visibilitySamples;
  std::vector<Polygon> storage;
  const auto piecesOfElements = piecesOfMesh(mesh, storage);
  RefinePass pass;
  pass.elements = mesh.size();
  const auto ffStart = Clock::now();
  const FormFactorMatrix F = updateFormFactors(FormFactorMatrix(), {}, piecesOfElements, visibility, transfer,
                                               progress, "form factors", pass.pairsComputed);
  solution.stats.formFactorSeconds = secondsSince(ffStart);
  const auto solveStart = Clock::now();
  RgbField B = mesh.emission;
  pass.sweeps = gatherSolve(RadiositySystem::fromMesh(mesh, F), B, options.solverTolerance, options.maxSweeps,
                            progress);
  solution.stats.solveSeconds = secondsSince(solveStart);
  pass.seconds = secondsSince(start);
  solution.stats.passes.push_back(pass);
  solution.stats.pairsComputed = pass.pairsComputed;

  solution.tVertices = findTVertices(mesh);
  solution.elementLevel.assign(mesh.size(), 0);
  solution.mesh = std::move(mesh);
  solution.B = std::move(B);
  solution.stats.elements = solution.mesh.size();
  solution.stats.tVertices = solution.tVertices.size();
  solution.stats.raysCast = visibility.raysCast();
  solution.stats.seconds = secondsSince(start);
  return solution;
}

}  // namespace rt
