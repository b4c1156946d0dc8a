// U, the unoccluded form factor of one pair over the source, to a tolerance (stage 3 of README.md): Gauss
// quadrature of Lambert's formula with the order read off the a-priori bound (source_panels.h), panels split
// where it would exceed the highest order, and far pairs taken at one point on each side where the bound
// allows it.
#pragma once

#include <vector>

#include "core/formfactor/quadrature/hidden_integral.h"
#include "core/formfactor/quadrature/quadrature_scene.h"
#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/quadrature/source_panels.h"

namespace rt {

// One side of a far pair as its one-point rule sees it: the node and weight, and the longest edge.
struct OnePoint {
  Vec3 node = Vec3::Zero();
  double weight = 0, longest = 0;
  int corners = 0;  // 0: none (not a single triangle or quadrilateral)
};

// An element's own one-point rule, made once with its other measures (it is whole).
OnePoint onePointOf(const QuadratureScene::Measure& m);

// int over `panel` of F(dA_x -> receiver) dA_x to `tolerance`. `gap` and `edge`, where known (>= 0), are
// panelGap() and the longest edge of the panel. `far`, where given, is the receiver's one-point rule, and
// `own` the panel's where known (the element whole).
double integrateUnoccluded(const SourcePanel& panel, const ReceiverBound& bound,
                           const ConvexPolygon& receiver, const Vec3& normal, double tolerance, int depth,
                           PairWork& work, double gap = -1, double edge = -1, const OnePoint* far = nullptr,
                           const OnePoint* own = nullptr);

// A convex polygon as panels (panelsOf()), appended to `out`; convex polygons as panels, into `out`.
void appendPanels(const ConvexPolygon& polygon, std::vector<SourcePanel>& out);
void appendPanels(const std::vector<ConvexPolygon>& polygons, std::vector<SourcePanel>& out);

}  // namespace rt
