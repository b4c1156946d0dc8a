#include "exact/discontinuity_triangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace rt::exact {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// Exact_predicates_tag: constraints may cross; their intersection points are constructed in floating point.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, CGAL::Default, CGAL::Exact_predicates_tag>;
using Point = Cdt::Point;

Point toPoint(const Vec2& p) {
  return Point(p.x(), p.y());
}

// Inserts a-b as a chain of constrained pieces no longer than `step`, so that long critical lines and
// boundary edges do not force long thin triangles.
void insertChain(Cdt& cdt, const Vec2& a, const Vec2& b, double step) {
  const int pieces = step > 0 ? std::max(1, static_cast<int>(std::ceil((b - a).norm() / step))) : 1;
  Vec2 previous = a;
  for (int k = 1; k <= pieces; ++k) {
    const Vec2 next = k == pieces ? b : Vec2(a + (b - a) * (static_cast<double>(k) / pieces));
    cdt.insert_constraint(toPoint(previous), toPoint(next));
    previous = next;
  }
}

bool insideConvex(const std::vector<Vec2>& boundary, const Vec2& p, double eps) {
  for (std::size_t k = 0; k < boundary.size(); ++k) {
    const Vec2 e = boundary[(k + 1) % boundary.size()] - boundary[k];
    const Vec2 d = p - boundary[k];
    if (e.x() * d.y() - e.y() * d.x() < -eps * e.norm()) return false;
  }
  return true;
}

}  // namespace

rt::PlanarTriangulation triangulateWithConstraints(const rt::PlanarDomain& domain) {
  if (domain.boundary.size() < 3)
    throw std::invalid_argument("constrained triangulation: boundary needs 3 points");
  // Element size comes from Steiner points on a grid and from splitting the constraints, not from CGAL's
  // Delaunay refinement (Mesh_2): with inexact constructions, refinement next to nearly parallel crossing
  // critical lines can corrupt the triangulation, while plain insertion into the constrained triangulation is
  // robust.
  const double step = domain.maxEdge > 0 ? 0.5 * domain.maxEdge : 0.0;
  Cdt cdt;
  const std::size_t n = domain.boundary.size();
  for (std::size_t k = 0; k < n; ++k)
    insertChain(cdt, domain.boundary[k], domain.boundary[(k + 1) % n], step);
  for (const auto& [a, b] : domain.constraints)
    if ((a - b).norm() > 0) insertChain(cdt, a, b, step);
  Eigen::AlignedBox2d box;
  for (const Vec2& p : domain.boundary) box.extend(p);
  const double size = box.diagonal().norm();
  if (step > 0) {
    // Interior grid points, kept away from the boundary by half a step.
    for (double x = box.min().x() + step; x < box.max().x(); x += step)
      for (double y = box.min().y() + step; y < box.max().y(); y += step) {
        const Vec2 p(x, y);
        if (insideConvex(domain.boundary, p, -0.25 * step)) cdt.insert(toPoint(p));
      }
  }

  rt::PlanarTriangulation out;
  std::map<Cdt::Vertex_handle, int> index;
  auto indexOf = [&](Cdt::Vertex_handle v) {
    const auto [it, added] = index.emplace(v, static_cast<int>(out.points.size()));
    if (added) out.points.emplace_back(v->point().x(), v->point().y());
    return it->second;
  };
  for (Cdt::Finite_faces_iterator f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const Vec2 a(f->vertex(0)->point().x(), f->vertex(0)->point().y());
    const Vec2 b(f->vertex(1)->point().x(), f->vertex(1)->point().y());
    const Vec2 c(f->vertex(2)->point().x(), f->vertex(2)->point().y());
    // Constraint ends rounded a hair outside the boundary would add slivers outside the domain.
    if (!insideConvex(domain.boundary, (a + b + c) / 3.0, 1e-9 * size)) continue;
    // CGAL's faces are counter-clockwise.
    out.triangles.push_back({indexOf(f->vertex(0)), indexOf(f->vertex(1)), indexOf(f->vertex(2))});
  }
  return out;
}

void registerDiscontinuityTriangulation() {
  rt::setConstrainedTriangulator(triangulateWithConstraints, "CGAL constrained Delaunay");
}

}  // namespace rt::exact
