#include "core/refine/refine.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/input_error.h"
#include "core/polygon.h"
#include "core/refine/refine_modes.h"

namespace rt {
namespace {

RefineOptions resolved(const Scene& scene, RefineOptions o) {
  auto positive = [](double v) { return std::isfinite(v) && v >= 0; };
  if (!positive(o.initialMaxEdge)) throw InputError({}, "refine: the initial edge length must be >= 0");
  if (!positive(o.minEdge)) throw InputError({}, "refine: the minimum edge length must be >= 0");
  if (!positive(o.discontinuityMaxEdge))
    throw InputError({}, "refine: the discontinuity edge length must be >= 0");
  if (!positive(o.minArea)) throw InputError({}, "refine: the minimum area must be >= 0");
  if (!(o.gradientTolerance > 0 && std::isfinite(o.gradientTolerance)))
    throw InputError({}, "refine: the gradient tolerance must be positive");
  if (!(o.linkTolerance > 0 && std::isfinite(o.linkTolerance)))
    throw InputError({}, "refine: the link tolerance must be positive");
  if (o.visibilitySamples < 1) throw InputError({}, "refine: visibility needs at least 1 sample");
  if (o.maxPasses < 1) throw InputError({}, "refine: at least one pass is needed");
  if (o.maxElements < 1) throw InputError({}, "refine: the element budget must be positive");
  if (scene.patches.empty()) throw InputError({scene.sourceFile, 0, ""}, "refine: the scene has no patches");
  if (o.initialMaxEdge == 0) o.initialMaxEdge = defaultInitialMaxEdge(scene);
  if (o.minEdge == 0) o.minEdge = o.initialMaxEdge / 16;
  if (o.discontinuityMaxEdge == 0) o.discontinuityMaxEdge = o.initialMaxEdge;
  if (o.minArea == 0) o.minArea = o.minEdge * o.minEdge;
  return o;
}

bool containsPoint(const Polygon& polygon, const Vec3& normal, const Vec3& p, double eps) {
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Vec3& a = polygon[k];
    const Vec3& b = polygon[(k + 1) % polygon.size()];
    if ((b - a).cross(p - a).dot(normal) < -eps * (b - a).norm()) return false;
  }
  return true;
}

}  // namespace

std::string toString(RefineMode mode) {
  switch (mode) {
    case RefineMode::Uniform:
      return "uniform";
    case RefineMode::Adaptive:
      return "adaptive";
    case RefineMode::Discontinuity:
      return "discontinuity";
    case RefineMode::Hierarchical:
      return "hierarchical";
  }
  return "unknown";
}

RefineMode refineModeFromString(const std::string& name) {
  for (RefineMode m :
       {RefineMode::Uniform, RefineMode::Adaptive, RefineMode::Discontinuity, RefineMode::Hierarchical})
    if (toString(m) == name) return m;
  throw InputError({}, "unknown mesh refinement '" + name +
                           "' (expected uniform, adaptive, discontinuity or "
                           "hierarchical)");
}

double luminance(const Eigen::Ref<const Eigen::RowVector3d>& rgb) {
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

double meanReflectingLuminance(const Mesh& mesh, const RgbField& B) {
  double weighted = 0, area = 0, weightedAll = 0, areaAll = 0;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    const double a = mesh.elements[i].area, y = luminance(B.row(row));
    weightedAll += a * y;
    areaAll += a;
    if ((mesh.emission.row(row).array() > 0).any()) continue;
    weighted += a * y;
    area += a;
  }
  if (area <= 0) weighted = weightedAll, area = areaAll;
  return area > 0 ? weighted / area : 0.0;
}

double defaultInitialMaxEdge(const Scene& scene) {
  const Eigen::AlignedBox3d box = scene.bounds();
  // A fifth of the diagonal: about 190 mm in the Cornell box, which meshes it into ~140 elements.
  return box.isEmpty() ? 1.0 : box.diagonal().norm() / 5.0;
}

std::string RefineStats::summary() const {
  std::ostringstream s;
  s.precision(3);
  s << toString(mode) << ": " << initialElements << " -> " << elements << " elements";
  if (!passes.empty()) s << " in " << passes.size() << " pass" << (passes.size() == 1 ? "" : "es");
  if (mode == RefineMode::Hierarchical)
    s << ", " << links << " links (n^2 = " << static_cast<double>(elements) * static_cast<double>(elements)
      << "), " << hierarchyNodes << " nodes, depth " << maxLevel;
  else
    s << ", " << pairsComputed << " form-factor pairs";
  if (criticalSegments) s << ", " << criticalSegments << " critical segments";
  if (tVertices) s << ", " << tVertices << " T-vertices";
  s << ", " << raysCast << " rays, " << seconds << " s (form factors " << formFactorSeconds << " s, solve "
    << solveSeconds << " s)";
  if (!notes.empty()) s << ", " << notes;
  return s.str();
}

RefinedSolution solveRefined(const Scene& scene, const RefineOptions& requested, Progress& progress) {
  const RefineOptions options = resolved(scene, requested);
  switch (options.mode) {
    case RefineMode::Uniform:
      return solveUniform(scene, options, progress);
    case RefineMode::Adaptive:
      return solveAdaptive(scene, options, progress);
    case RefineMode::Discontinuity:
      return solveDiscontinuity(scene, options, progress);
    case RefineMode::Hierarchical:
      return solveHierarchical(scene, options, progress);
  }
  throw InputError({}, "unknown mesh refinement");
}

Mesh conformingDisplayMesh(const RefinedSolution& solution, std::vector<int>* sourceElement) {
  const Mesh& in = solution.mesh;
  std::vector<std::vector<const TVertex*>> hanging(in.size());
  for (const TVertex& t : solution.tVertices) hanging[t.element].push_back(&t);
  Mesh out;
  out.vertices = in.vertices;
  std::vector<int> source;
  auto addElement = [&](std::vector<int> vertices, int from) {
    Element e;
    e.vertices = std::move(vertices);
    e.patch = in.elements[from].patch;
    e.normal = in.elements[from].normal;
    Polygon p;
    for (int v : e.vertices) p.push_back(out.vertices[v]);
    e.area = polygonArea(p);
    e.centroid = polygonCentroid(p);
    out.elements.push_back(std::move(e));
    source.push_back(from);
  };
  for (std::size_t e = 0; e < in.size(); ++e) {
    const Element& element = in.elements[e];
    if (hanging[e].empty()) {
      addElement(element.vertices, static_cast<int>(e));
      continue;
    }
    std::vector<int> loop;
    const std::size_t n = element.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      const int a = element.vertices[k], b = element.vertices[(k + 1) % n];
      loop.push_back(a);
      std::vector<const TVertex*> onEdge;
      for (const TVertex* t : hanging[e])
        if (t->edgeStart == a && t->edgeEnd == b) onEdge.push_back(t);
      std::sort(onEdge.begin(), onEdge.end(), [](const TVertex* x, const TVertex* y) { return x->t < y->t; });
      for (const TVertex* t : onEdge) loop.push_back(t->vertex);
    }
    const int centre = static_cast<int>(out.vertices.size());
    out.vertices.push_back(element.centroid);
    for (std::size_t k = 0; k < loop.size(); ++k)
      addElement({centre, loop[k], loop[(k + 1) % loop.size()]}, static_cast<int>(e));
  }
  out.vertexElements.assign(out.vertices.size(), {});
  for (std::size_t e = 0; e < out.elements.size(); ++e)
    for (int v : out.elements[e].vertices) out.vertexElements[v].push_back(static_cast<int>(e));
  out.reflectance.resize(static_cast<Eigen::Index>(source.size()), 3);
  out.emission.resize(static_cast<Eigen::Index>(source.size()), 3);
  for (std::size_t k = 0; k < source.size(); ++k) {
    out.reflectance.row(static_cast<Eigen::Index>(k)) = in.reflectance.row(source[k]);
    out.emission.row(static_cast<Eigen::Index>(k)) = in.emission.row(source[k]);
  }
  if (sourceElement) *sourceElement = std::move(source);
  return out;
}

RgbField vertexRadiosity(const RefinedSolution& solution) {
  const Mesh& mesh = solution.mesh;
  RgbField V = RgbField::Zero(static_cast<Eigen::Index>(mesh.vertices.size()), 3);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    double area = 0;
    for (int e : mesh.vertexElements[v]) {
      V.row(static_cast<Eigen::Index>(v)) += mesh.elements[e].area * solution.B.row(e);
      area += mesh.elements[e].area;
    }
    if (area > 0) V.row(static_cast<Eigen::Index>(v)) /= area;
  }
  // Hanging vertices take the value interpolated along the edge they sit on, so that the larger element's
  // shading and the smaller ones' agree there (no crack in the shading). Nested hanging vertices settle in a
  // few rounds.
  for (int round = 0; round < 4; ++round)
    for (const TVertex& t : solution.tVertices)
      V.row(t.vertex) = (1 - t.t) * V.row(t.edgeStart) + t.t * V.row(t.edgeEnd);
  return V;
}

Rgb radiosityAt(const RefinedSolution& solution, int patch, const Vec3& point) {
  const Mesh& mesh = solution.mesh;
  int best = -1;
  double bestDistance = 0;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& element = mesh.elements[e];
    if (element.patch != patch) continue;
    const Polygon p = mesh.polygon(static_cast<int>(e));
    if (containsPoint(p, element.normal, point, 1e-9))
      return solution.B.row(static_cast<Eigen::Index>(e)).array();
    const double d = (element.centroid - point).norm();
    if (best < 0 || d < bestDistance) best = static_cast<int>(e), bestDistance = d;
  }
  return best < 0 ? Rgb::Zero() : Rgb(solution.B.row(best).array());
}

Rgb interpolatedRadiosityAt(const RefinedSolution& solution, int patch, const Vec3& point) {
  const Mesh& mesh = solution.mesh;
  auto vertexValue = [&](int v) {
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    double area = 0;
    for (int e : mesh.vertexElements[v])
      if (mesh.elements[e].patch == patch) {
        sum += mesh.elements[e].area * solution.B.row(e);
        area += mesh.elements[e].area;
      }
    return Eigen::RowVector3d(area > 0 ? Eigen::RowVector3d(sum / area) : sum);
  };
  int best = -1;
  double bestDistance = 0;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& element = mesh.elements[e];
    if (element.patch != patch) continue;
    const auto& v = element.vertices;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
      const Vec3 &a = mesh.vertices[v[0]], &b = mesh.vertices[v[k]], &c = mesh.vertices[v[k + 1]];
      const double whole = (b - a).cross(c - a).dot(element.normal);
      if (whole <= 0) continue;
      const double wa = (b - point).cross(c - point).dot(element.normal) / whole;
      const double wb = (c - point).cross(a - point).dot(element.normal) / whole;
      const double wc = 1 - wa - wb;
      if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
      return (wa * vertexValue(v[0]) + wb * vertexValue(v[k]) + wc * vertexValue(v[k + 1]))
          .transpose()
          .array();
    }
    const double d = (element.centroid - point).norm();
    if (best < 0 || d < bestDistance) best = static_cast<int>(e), bestDistance = d;
  }
  return best < 0 ? Rgb::Zero() : Rgb(solution.B.row(best).array());
}

double relativeRmsError(const RefinedSolution& solution, const RefinedSolution& reference,
                        bool interpolated) {
  double sum = 0, mean = 0, area = 0;
  for (std::size_t e = 0; e < reference.mesh.size(); ++e) {
    const Element& element = reference.mesh.elements[e];
    if ((reference.mesh.emission.row(static_cast<Eigen::Index>(e)).array() > 0).any()) continue;
    const double ref = luminance(reference.B.row(static_cast<Eigen::Index>(e)));
    const Rgb value = interpolated ? interpolatedRadiosityAt(solution, element.patch, element.centroid)
                                   : radiosityAt(solution, element.patch, element.centroid);
    const double got = luminance(value.matrix().transpose());
    sum += element.area * (got - ref) * (got - ref);
    mean += element.area * ref;
    area += element.area;
  }
  if (area <= 0 || mean <= 0) return 0;
  return std::sqrt(sum / area) / (mean / area);
}

}  // namespace rt
