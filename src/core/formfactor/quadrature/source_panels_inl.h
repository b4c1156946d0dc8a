// The inner loop of source_panels.h, inline: it runs once per Gauss point, millions of times per matrix.
#pragma once

#include "core/formfactor/gauss_legendre.h"

namespace rt {

template <class Visit>
void forEachGaussPoint(const SourcePanel& panel, int n, Visit&& visit) {
  const QuadratureRule& rule = gaussLegendre(n);
  const Vec3& a = panel.v[0];
  if (panel.count == 4) {
    // Bilinear map of the unit square: x(u, v) = a + u ab + v ad + u v (a - b + c - d).
    const Vec3 ab = panel.v[1] - a, ad = panel.v[3] - a, twist = a - panel.v[1] + panel.v[2] - panel.v[3];
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double u = rule.nodes[static_cast<std::size_t>(i)], v = rule.nodes[static_cast<std::size_t>(j)];
        const Vec3 du = ab + v * twist, dv = ad + u * twist;
        visit(Vec3(a + u * ab + v * ad + (u * v) * twist), rule.weights[static_cast<std::size_t>(i)] *
                                                               rule.weights[static_cast<std::size_t>(j)] *
                                                               du.cross(dv).norm());
      }
    return;
  }
  // Collapsed square: x(u, v) = a + u (b - a) + u v (c - b), Jacobian u |(b - a) x (c - b)|.
  const Vec3 e1 = panel.v[1] - a, e2 = panel.v[2] - panel.v[1];
  const double scale = e1.cross(e2).norm();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = rule.nodes[static_cast<std::size_t>(i)], v = rule.nodes[static_cast<std::size_t>(j)];
      visit(Vec3(a + u * e1 + (u * v) * e2), rule.weights[static_cast<std::size_t>(i)] *
                                                 rule.weights[static_cast<std::size_t>(j)] * u * scale);
    }
}

}  // namespace rt
