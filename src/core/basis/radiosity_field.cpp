#include "core/basis/radiosity_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/formfactor/gauss_legendre.h"

namespace rt {
namespace {

std::vector<std::vector<int>> elementsByPatch(const Mesh& mesh) {
  std::vector<std::vector<int>> out;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const auto p = static_cast<std::size_t>(mesh.elements[e].patch);
    if (out.size() <= p) out.resize(p + 1);
    out[p].push_back(static_cast<int>(e));
  }
  return out;
}

// Sum over f's Gauss points of w |f - g| and w |g|, per channel.
struct L1Sums {
  Rgb difference = Rgb::Zero(), reference = Rgb::Zero();
  double ratio() const {
    double num = 0, den = 0;
    for (int c = 0; c < 3; ++c) {
      num += difference[c];
      den += reference[c];
    }
    return den > 0 ? num / den : num;
  }
};

void integrate(const Mesh& mesh, int order, const std::function<bool(int)>& include,
               const std::function<void(int element, double u, double v, const Vec3& x, double w)>& add) {
  const QuadratureRule& rule = gaussLegendre(order);
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    if (include && !include(mesh.elements[e].patch)) continue;
    const ElementMap map(mesh, static_cast<int>(e));
    for (std::size_t a = 0; a < rule.nodes.size(); ++a)
      for (std::size_t b = 0; b < rule.nodes.size(); ++b) {
        const double u = rule.nodes[a], v = rule.nodes[b];
        add(static_cast<int>(e), u, v, map.point(u, v),
            rule.weights[a] * rule.weights[b] * map.jacobian(u, v));
      }
  }
}

}  // namespace

RadiosityField::RadiosityField(const Mesh& mesh, const RgbField& perElement)
    : mesh_(&mesh), values_(&perElement), patchElements_(elementsByPatch(mesh)) {}

RadiosityField::RadiosityField(const Mesh& mesh, const LinearBasis& basis, const RgbField& nodal)
    : mesh_(&mesh), basis_(&basis), values_(&nodal), patchElements_(elementsByPatch(mesh)) {}

Rgb RadiosityField::at(int element, double u, double v) const {
  if (!basis_) return values_->row(element).transpose().array();
  return basis_->valueAt(*mesh_, *values_, element, u, v);
}

Rgb RadiosityField::at(const Vec3& point, int patch) const {
  ElementCoordinates best;
  best.distance = std::numeric_limits<double>::infinity();
  int bestElement = -1;
  if (patch < 0 || static_cast<std::size_t>(patch) >= patchElements_.size()) return Rgb::Zero();
  for (const int e : patchElements_[static_cast<std::size_t>(patch)]) {
    const ElementCoordinates c = elementCoordinates(*mesh_, e, point);
    if (c.distance < best.distance) {
      best = c;
      bestElement = e;
      if (c.distance <= 1e-12 * std::sqrt(mesh_->elements[static_cast<std::size_t>(e)].area)) break;
    }
  }
  return bestElement < 0 ? Rgb::Zero() : at(bestElement, best.u, best.v);
}

ElementCoordinates elementCoordinates(const Mesh& mesh, int element, const Vec3& point) {
  const ElementMap map(mesh, element);
  ElementCoordinates c;
  if (map.count == 3) {
    // Barycentric coordinates in the plane, clamped, then the collapsed square's (u, v).
    const Vec3 e1 = map.p[1] - map.p[0], e2 = map.p[2] - map.p[0], d = point - map.p[0];
    const double a = e1.dot(e1), b = e1.dot(e2), cc = e2.dot(e2), p = d.dot(e1), q = d.dot(e2);
    const double det = a * cc - b * b;
    double l1 = det > 0 ? (cc * p - b * q) / det : 0, l2 = det > 0 ? (a * q - b * p) / det : 0;
    l1 = std::max(0.0, l1);
    l2 = std::max(0.0, l2);
    if (l1 + l2 > 1) {
      const double s = l1 + l2;
      l1 /= s;
      l2 /= s;
    }
    c.u = l1 + l2;
    c.v = c.u > 0 ? l2 / c.u : 0;
  } else {
    // Newton on the bilinear map, least squares in 3D (the point lies in the element's plane).
    c.u = c.v = 0.5;
    for (int k = 0; k < 12; ++k) {
      const Vec3 r = map.point(c.u, c.v) - point;
      const Vec3 du = (1 - c.v) * (map.p[1] - map.p[0]) + c.v * (map.p[2] - map.p[3]);
      const Vec3 dv = (1 - c.u) * (map.p[3] - map.p[0]) + c.u * (map.p[2] - map.p[1]);
      const double a = du.dot(du), b = du.dot(dv), cc = dv.dot(dv), det = a * cc - b * b;
      if (det <= 0) break;
      const double p = du.dot(r), q = dv.dot(r);
      c.u = std::clamp(c.u - (cc * p - b * q) / det, 0.0, 1.0);
      c.v = std::clamp(c.v - (a * q - b * p) / det, 0.0, 1.0);
    }
  }
  c.distance = (map.point(c.u, c.v) - point).norm();
  return c;
}

double relativeL1Difference(const RadiosityField& f, const std::function<Rgb(const Vec3&, int patch)>& g,
                            int order, const std::function<bool(int patch)>& include) {
  L1Sums sums;
  integrate(f.mesh(), order, include, [&](int e, double u, double v, const Vec3& x, double w) {
    const Rgb exact = g(x, f.mesh().elements[static_cast<std::size_t>(e)].patch);
    sums.difference += w * (f.at(e, u, v) - exact).abs();
    sums.reference += w * exact.abs();
  });
  return sums.ratio();
}

double relativeL1Difference(const RadiosityField& f, const RadiosityField& reference, int order,
                            const std::function<bool(int patch)>& include) {
  L1Sums sums;
  integrate(reference.mesh(), order, include, [&](int e, double u, double v, const Vec3& x, double w) {
    const Rgb exact = reference.at(e, u, v);
    sums.difference +=
        w * (f.at(x, reference.mesh().elements[static_cast<std::size_t>(e)].patch) - exact).abs();
    sums.reference += w * exact.abs();
  });
  return sums.ratio();
}

}  // namespace rt
