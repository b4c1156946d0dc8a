// Gauss-Legendre quadrature over the source of a form factor, with the order chosen a priori.
//
//   F_ij = (1/A_i) int_i F(dA_x -> j) dA_x
//
// Lambert's point-to-polygon formula F(dA_x -> j) is analytic in x over the source as long as x stays away
// from the receiver: its nearest complex singularity lies at the receiver. An n-point Gauss rule on a panel
// of length h whose nearest singularity is a distance d away errs by about M rho^-2n, with rho the Bernstein
// ellipse through the singularity, rho = 2 d/h + sqrt(1 + 4 d^2/h^2), and M the size of the integrand there,
// at most A_j / (pi d^2) (the solid angle of j over pi). So the order that meets an absolute tolerance tau is
// read off before any evaluation, and a panel that would need too high an order is split in four instead
// (each child is twice as far from the receiver, in its own lengths).
//
// Panels are planar convex triangles and quadrilaterals: a quadrilateral by the bilinear tensor rule, a
// triangle by the collapsed (Duffy) tensor rule, n x n points either way.
#pragma once

#include <array>

#include "core/geometry/convex_polygon.h"
#include "core/vec.h"

namespace rt {

// A panel: a convex polygon of 3 or 4 corners (area(), centre() the corner mean, radius(), longestEdge()).
using SourcePanel = FixedConvexPolygon<4>;

// Four children covering the panel: by edge midpoints (and the centre, for a quadrilateral).
std::array<SourcePanel, 4> splitPanel(const SourcePanel& panel);

// Calls visit(x, weight) for the n x n points of the panel's rule; the weights sum to the panel's area.
template <class Visit>
void forEachGaussPoint(const SourcePanel& panel, int n, Visit&& visit);

// The points of one rule, for callers that evaluate a panel more than once.
struct PanelPoints {
  static constexpr int kMax = 12 * 12;
  std::array<Vec3, kMax> x;
  std::array<double, kMax> weight;
  int count = 0;
};
void gaussPoints(const SourcePanel& panel, int n, PanelPoints& out);

// The receiver as the a-priori bound sees it: a plane and a bounding sphere.
struct ReceiverBound {
  Vec3 point, normal;  // its plane (normal unit, towards the front)
  Vec3 centre;
  double radius = 0;
  double area = 0;
};

// A lower bound of the distance from the panel to the receiver: the larger of the gap between bounding
// spheres and the panel's least height above the receiver's plane.
double panelGap(const SourcePanel& panel, const ReceiverBound& receiver);

// The least Gauss order (1..kMaxOrder) whose a-priori error bound on this panel is below `tolerance`
// (absolute, in units of F(dA -> j)); 0 when no order up to kMaxOrder suffices (split the panel).
constexpr int kMaxOrder = 8;
int gaussOrderFor(const SourcePanel& panel, const ReceiverBound& receiver, double tolerance);
// The same from the panel's gap (panelGap()), longest edge and corner count, for callers that know them.
int gaussOrderFor(double gap, double h, int corners, double receiverArea, double tolerance);

// A convex polygon as panels: itself when it has 3 or 4 vertices, otherwise a fan of quadrilaterals (and
// one triangle).
int panelsOf(const Vec3* polygon, int count, SourcePanel* out, int capacity);

}  // namespace rt

#include "core/formfactor/quadrature/source_panels_inl.h"
