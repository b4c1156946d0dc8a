#include "core/formfactor/quadrature/quadrature_scene.h"

#include <algorithm>
#include <cmath>

#include "core/formfactor/quadrature/closed_solids.h"
#include "core/formfactor/quadrature/shadow_overlap.h"
#include "core/formfactor/visibility.h"
#include "core/polygon.h"

namespace rt {

ReceiverBound boundOf(const ConvexPolygon& receiver, const Vec3& normal) {
  ReceiverBound bound{receiver.v[0], normal, Vec3::Zero(), 0, 0};
  Vec3 twice = Vec3::Zero();
  for (int k = 0; k < receiver.count; ++k) {
    bound.centre += receiver.v[static_cast<std::size_t>(k)];
    twice += receiver.v[static_cast<std::size_t>(k)].cross(
        receiver.v[static_cast<std::size_t>((k + 1) % receiver.count)]);
  }
  bound.centre /= receiver.count;
  for (int k = 0; k < receiver.count; ++k)
    bound.radius = std::max(bound.radius, (receiver.v[static_cast<std::size_t>(k)] - bound.centre).norm());
  bound.area = 0.5 * twice.norm();
  return bound;
}

QuadratureScene::QuadratureScene(const Mesh& mesh_, const ShaftCulling& shafts_)
    : mesh(mesh_), shafts(shafts_) {
  const std::size_t patches = shafts.patchCount();
  std::vector<double> patchArea(patches, 0.0);
  patchElements.resize(patches);
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    patchArea[static_cast<std::size_t>(mesh.elements[e].patch)] += mesh.elements[e].area;
    patchElements[static_cast<std::size_t>(mesh.elements[e].patch)].push_back(static_cast<int>(e));
  }
  convex.assign(patches, false);
  elementPolygons.resize(mesh.size());
  for (std::size_t k = 0; k < patches; ++k) {
    const std::vector<Vec3>& outline = shafts.outline(static_cast<int>(k));
    convex[k] = std::abs(polygonArea(outline) - patchArea[k]) <= 1e-9 * patchArea[k];
    if (!convex[k])
      for (int e : patchElements[k]) elementPolygons[static_cast<std::size_t>(e)] = mesh.polygon(e);
  }
  static const std::vector<Vec3> none;
  std::vector<const std::vector<Vec3>*> outlines;
  for (std::size_t k = 0; k < patches; ++k)
    outlines.push_back(convex[k] ? &shafts.outline(static_cast<int>(k)) : &none);
  // Blocks given without a bottom are closed by a face of their own (closingFaces()), after the patches.
  const std::vector<std::vector<Vec3>> closing = closingFaces(outlines);
  for (const std::vector<Vec3>& face : closing) outlines.push_back(&face);
  solidOf = closedConvexSolids(outlines, solids);
  shapes = solidShapes(outlines, solidOf, static_cast<int>(solids.size()));
  solidOf.resize(patches);
  for (const SolidShape& shape : shapes) solidCentres.push_back(shape.centre);

  elementSolids.resize(mesh.size());
  enclosed.assign(mesh.size(), 0);
  measures.resize(mesh.size());
  std::vector<std::vector<Vec3>> polygons;
  std::vector<Vec3> normals;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const ConvexPolygon polygon = elementPolygon(mesh, static_cast<int>(e));
    measures[e].bound = boundOf(polygon, mesh.elements[e].normal);
    for (int k = 0; k < polygon.count; ++k)
      measures[e].longest =
          std::max(measures[e].longest, (polygon.v[static_cast<std::size_t>((k + 1) % polygon.count)] -
                                         polygon.v[static_cast<std::size_t>(k)])
                                            .norm());
    if (polygon.count <= 4) {
      SourcePanel panel;
      panel.assign(polygon);
      forEachGaussPoint(panel, 1,
                        [&](const Vec3& x, double w) { measures[e].node = x, measures[e].weight = w; });
      measures[e].corners = polygon.count;
    }
    if (solids.empty()) continue;
    const double eps = 1e-9 * std::sqrt(mesh.elements[e].area);
    const int own = solidOf[static_cast<std::size_t>(mesh.elements[e].patch)];
    for (std::size_t s = 0; s < solids.size(); ++s) {
      if (static_cast<int>(s) == own) continue;
      const double inside = areaInside(polygon, solids[s], eps);
      if (inside > 1e-9 * mesh.elements[e].area) elementSolids[e].push_back(static_cast<int>(s));
      if (inside >= (1 - 1e-9) * mesh.elements[e].area) enclosed[e] = 1;
    }
    polygons.emplace_back(polygon.v.begin(), polygon.v.begin() + polygon.count);
    normals.push_back(mesh.elements[e].normal);
  }
  double size = 0;
  for (const Vec3& v : mesh.vertices) size = std::max(size, v.cwiseAbs().maxCoeff());
  regionEps = 1e-10 * size;
  contactRegions = std::make_unique<ContactShadowRegions>(shapes, static_cast<int>(polygons.size()), polygons,
                                                          normals, regionEps);
  const double entries =
      static_cast<double>(mesh.size()) * static_cast<double>(solids.size() * solids.size());
  if (solids.size() >= 2 && entries <= static_cast<double>(kMaxApartEntries))
    outsideHull_ = std::vector<std::atomic<signed char>>(mesh.size() * solids.size() * solids.size());
}

bool QuadratureScene::outsideHull(int element, int near, int other) const {
  const std::size_t n = solids.size();
  std::atomic<signed char>& known =
      outsideHull_[(static_cast<std::size_t>(element) * n + static_cast<std::size_t>(near)) * n +
                   static_cast<std::size_t>(other)];
  signed char answer = known.load(std::memory_order_relaxed);
  if (answer == 0) {
    const ConvexPolygon polygon = elementPolygon(mesh, element);
    answer = solidOutsideHullOfSolidAndPolygon(shapes[static_cast<std::size_t>(other)],
                                               shapes[static_cast<std::size_t>(near)], polygon.v.data(),
                                               polygon.count, regionEps)
                 ? 1
                 : 2;
    known.store(answer, std::memory_order_relaxed);
  }
  return answer == 1;
}

bool QuadratureScene::shadowsApart(int source, int receiver, int a, int b) const {
  if (outsideHull_.empty() || a == b) return false;
  const int elements[2] = {source, receiver}, pair[2] = {a, b};
  return shadowsApartBy(
      [&](int e, int near, int other) { return outsideHull(elements[e], pair[near], pair[other]); });
}

}  // namespace rt
