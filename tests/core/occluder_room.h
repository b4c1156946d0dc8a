// A closed unit room lit by a small square light under its ceiling, with convex occluders of any corner
// count (n-gon prisms standing or floating, n-gon discs two-sided as two coincident polygons back to back),
// and an independent reference for what the light sends to a receiver on the floor.
//
// The reference needs nothing of the quadrature method's machinery: from a point x of the light, a convex
// occluder wholly between the light's plane and the floor's hides from the floor exactly the convex hull of
// its corners projected from x onto the floor, so the hidden part of a receiver is the receiver cut to that
// hull (a 2D clip), and Lambert's formula gives its form factor. Where the occluders' shadows never overlap
// (the scenes below are laid out so), what they hide adds up. A composite Gauss rule over the light
// integrates it; the integrand is C^1 (a shadow's area moves smoothly with x), so the rule converges fast,
// and callers compare two rule sizes to state the reference's own error.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/formfactor/analytic.h"
#include "core/formfactor/gauss_legendre.h"
#include "core/io/scene_loader.h"
#include "core/mesh.h"
#include "core/polygon.h"
#include "formfactor_scenes.h"
#include "support/test_paths.h"

namespace rt::test {

inline void addPolygon(Scene& scene, Polygon corners, bool emitter = false) {
  Patch p;
  const Vec3 n = newellNormal(corners);
  p.vertices = std::move(corners);
  p.normal = n.normalized();
  p.area = 0.5 * n.norm();
  p.surface = emitter ? 1 : 0;
  scene.patches.push_back(p);
}

// The regular n-gon of radius r about (cx, cy) at height z, counter-clockwise seen from above.
inline Polygon ngon(int n, double cx, double cy, double r, double z) {
  Polygon p;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    p.push_back({cx + r * std::cos(a), cy + r * std::sin(a), z});
  }
  return p;
}

// A closed n-gon prism from z0 to z1, every face outward (top up, bottom down, sides out). Returns its
// corners (for the reference).
inline Polygon addPrism(Scene& s, int n, double cx, double cy, double r, double z0, double z1) {
  const Polygon top = ngon(n, cx, cy, r, z1), bottom = ngon(n, cx, cy, r, z0);
  addPolygon(s, top);
  addPolygon(s, Polygon(bottom.rbegin(), bottom.rend()));
  for (int k = 0; k < n; ++k) {
    const int next = (k + 1) % n;
    addPolygon(s, {bottom[static_cast<std::size_t>(k)], bottom[static_cast<std::size_t>(next)],
                   top[static_cast<std::size_t>(next)], top[static_cast<std::size_t>(k)]});
  }
  Polygon corners = top;
  corners.insert(corners.end(), bottom.begin(), bottom.end());
  return corners;
}

// A floating n-gon disc seen from both sides: two coincident polygons back to back. Returns its corners.
inline Polygon addDisc(Scene& s, int n, double cx, double cy, double r, double z) {
  const Polygon up = ngon(n, cx, cy, r, z);
  addPolygon(s, up);
  addPolygon(s, Polygon(up.rbegin(), up.rend()));
  return up;
}

// The room: patch 0 the floor (z = 0, facing up), then the ceiling and the four walls (facing in), patch 6
// the 0.2 m square light just under the ceiling's centre (facing down). Occluders come after.
inline constexpr int kFloorPatch = 0, kLightPatch = 6;
inline constexpr double kLightHeight = 0.999;

inline Scene litRoom() {
  Scene s = closedBox(1, 1, 1);
  for (Patch& p : s.patches) p.surface = 0;
  const double a = 0.4, b = 0.6, z = kLightHeight;
  addPolygon(s, {{a, a, z}, {a, b, z}, {b, b, z}, {b, a, z}}, true);
  return s;
}

// The elements of a patch.
// The full-size room, scenes/prism-room.json (a 40-sided prism, a 36-sided disc, the light 1 mm under the
// ceiling), meshed as docs/benchmarks.md has it: `--max-edge 0.5 --split-at-contacts`, 325 elements.
inline Mesh meshedPrismRoom() {
  MeshOptions options;
  options.mode = MeshOptions::Mode::MaxEdge;
  options.maxEdge = 0.5;
  options.splitAtContacts = true;
  return buildMesh(loadScene(sourcePath("scenes/prism-room.json")), options);
}

inline std::vector<int> elementsOf(const Mesh& mesh, int patch) {
  std::vector<int> out;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    if (mesh.elements[e].patch == patch) out.push_back(static_cast<int>(e));
  return out;
}

namespace reference_detail {

inline double cross2(double ax, double ay, double bx, double by) {
  return ax * by - ay * bx;
}

using Point2 = std::pair<double, double>;

// Convex hull, counter-clockwise (Andrew's monotone chain).
inline std::vector<Point2> hull(std::vector<Point2> p) {
  std::sort(p.begin(), p.end());
  std::vector<Point2> h(2 * p.size() + 1);
  std::size_t k = 0;
  auto turn = [&](const Point2& o, const Point2& a, const Point2& b) {
    return cross2(a.first - o.first, a.second - o.second, b.first - o.first, b.second - o.second);
  };
  for (const Point2& q : p) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], q) <= 0) --k;
    h[k++] = q;
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k > 0 ? k - 1 : 0);
  return h;
}

// `subject` (convex, counter-clockwise) cut to the inside of the convex counter-clockwise `clip`.
inline std::vector<Point2> clip(std::vector<Point2> subject, const std::vector<Point2>& clip) {
  for (std::size_t e = 0; e < clip.size() && subject.size() >= 3; ++e) {
    const Point2 &a = clip[e], &b = clip[(e + 1) % clip.size()];
    auto side = [&](const Point2& q) {
      return cross2(b.first - a.first, b.second - a.second, q.first - a.first, q.second - a.second);
    };
    std::vector<Point2> out;
    for (std::size_t k = 0; k < subject.size(); ++k) {
      const Point2 &p = subject[k], &q = subject[(k + 1) % subject.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0) out.push_back(p);
      if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) {
        const double t = sp / (sp - sq);
        out.push_back({p.first + t * (q.first - p.first), p.second + t * (q.second - p.second)});
      }
    }
    subject = std::move(out);
  }
  if (subject.size() < 3) subject.clear();
  return subject;
}

}  // namespace reference_detail

// F from the light (a parallelogram `light`, facing down) to `receiver` (on the floor z = 0, facing up),
// with `occluders` (each the corners of a convex body between the two planes, their shadows apart) taking
// away what they hide: an n x n grid of cells over the light, a 4 x 4 Gauss rule in each.
inline double referenceLightToFloor(const Polygon& light, const Polygon& receiver,
                                    const std::vector<Polygon>& occluders, int n) {
  using reference_detail::Point2;
  const Vec3 lightNormal = newellNormal(light).normalized();
  std::vector<Point2> floor;
  for (const Vec3& r : receiver) floor.push_back({r.x(), r.y()});  // counter-clockwise seen from above
  const QuadratureRule& rule = gaussLegendre(4);
  const Vec3 &o = light[0], du = light[1] - light[0], dv = light[3] - light[0];
  double sum = 0;
  Polygon hidden;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (std::size_t a = 0; a < rule.nodes.size(); ++a)
        for (std::size_t b = 0; b < rule.nodes.size(); ++b) {
          const Vec3 x = o + du * ((i + rule.nodes[a]) / n) + dv * ((j + rule.nodes[b]) / n);
          double value = lambertContourSum(x, lightNormal, receiver);
          for (const Polygon& body : occluders) {
            std::vector<Point2> shadow;
            for (const Vec3& c : body) {
              const Vec3 p = x + (c - x) * (x.z() / (x.z() - c.z()));
              shadow.push_back({p.x(), p.y()});
            }
            const std::vector<Point2> part = reference_detail::clip(floor, reference_detail::hull(shadow));
            if (part.empty()) continue;
            hidden.clear();
            for (const Point2& p : part) hidden.push_back({p.first, p.second, 0.0});
            value -= lambertContourSum(x, lightNormal, hidden);
          }
          sum += rule.weights[a] * rule.weights[b] * value / (static_cast<double>(n) * n);
        }
  return sum;
}

}  // namespace rt::test
