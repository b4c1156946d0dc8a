#include "exact/discontinuity_triangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <map>
#include <stdexcept>

namespace rt::exact {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_2<Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Exact_predicates_tag: constraints may cross; their intersection points are constructed in floating point.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, DataStructure, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Point = Cdt::Point;

Point toPoint(const Vec2& p) {
  return Point(p.x(), p.y());
}

}  // namespace

rt::PlanarTriangulation triangulateWithConstraints(const rt::PlanarDomain& domain) {
  if (domain.boundary.size() < 3)
    throw std::invalid_argument("constrained triangulation: boundary needs 3 points");
  Cdt cdt;
  const std::size_t n = domain.boundary.size();
  for (std::size_t k = 0; k < n; ++k)
    cdt.insert_constraint(toPoint(domain.boundary[k]), toPoint(domain.boundary[(k + 1) % n]));
  for (const auto& [a, b] : domain.constraints)
    if ((a - b).norm() > 0) cdt.insert_constraint(toPoint(a), toPoint(b));
  // Shape bound 0.125 is CGAL's default (minimum angle about 20.6 degrees); 0 as size means no size bound.
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, domain.maxEdge > 0 ? domain.maxEdge : 0.0));

  rt::PlanarTriangulation out;
  std::map<Cdt::Vertex_handle, int> index;
  auto indexOf = [&](Cdt::Vertex_handle v) {
    const auto [it, added] = index.emplace(v, static_cast<int>(out.points.size()));
    if (added) out.points.emplace_back(CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y()));
    return it->second;
  };
  for (Cdt::Finite_faces_iterator f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    // CGAL's faces are counter-clockwise.
    out.triangles.push_back({indexOf(f->vertex(0)), indexOf(f->vertex(1)), indexOf(f->vertex(2))});
  }
  return out;
}

void registerDiscontinuityTriangulation() {
  rt::setConstrainedTriangulator(triangulateWithConstraints, "CGAL constrained Delaunay");
}

}  // namespace rt::exact
