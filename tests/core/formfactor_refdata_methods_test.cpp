// Every public reference case (tests/data/refdata/formfactors.json) through every approximate method, each to
// a tolerance that follows from how it converges (the analytic method's 1e-9 is in formfactor_analytic_test).
// The cases become small scenes: each polygon a patch, a differential source a square of side 1e-4 around the
// point (its area-averaged F differs from the point's by ~1e-10), a disk a fan of 128 triangles (the
// inscribed polygons' F is 1.8e-4 below the disks', an allowance added to every tolerance of that case; the
// centroid methods skip it, since a fan of slivers meshed 16 x 16 would be 65,536 elements). A form factor
// between two groups of patches is the area-weighted sum over elements, F_SR = sum_{a in S} (A_a / A_S)
// sum_{b in R} F_ab, so the centroid methods can be meshed finer than the case's polygons.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/formfactor/formfactor_method.h"
#include "core/mesh.h"
#include "core/polygon.h"
#include "core/progress.h"
#include "support/test_paths.h"

namespace rt {
namespace {

using nlohmann::json;

Vec3 vec(const json& a) {
  return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()};
}

// A scene whose surfaces are the case's named groups (source, receiver, occluder, or the enclosure's faces).
struct CaseScene {
  Scene scene;
  std::map<std::string, int> group;  // name -> surface index
  void add(const std::string& name, const Polygon& polygon) {
    if (!group.count(name)) {
      group[name] = static_cast<int>(scene.surfaces.size());
      scene.surfaces.push_back({name, 0});
    }
    Patch p;
    p.vertices = polygon;
    const Vec3 n = newellNormal(polygon);
    p.normal = n.normalized();
    p.area = 0.5 * n.norm();
    p.surface = group[name];
    scene.patches.push_back(p);
  }
  void addShape(const std::string& name, const json& shape) {
    if (shape.contains("vertices")) {
      Polygon polygon;
      for (const json& v : shape["vertices"]) polygon.push_back(vec(v));
      add(name, polygon);
    } else if (shape.contains("point")) {  // differential: a tiny square facing along the normal
      const Vec3 c = vec(shape["point"]), n = vec(shape["normal"]).normalized();
      const Vec3 u = n.unitOrthogonal(), v = n.cross(u);
      const double h = 0.5e-4;
      add(name, {c - h * u - h * v, c + h * u - h * v, c + h * u + h * v, c - h * u + h * v});
    } else {  // disk: a fan of triangles, counter-clockwise seen from the normal's side
      const Vec3 c = vec(shape["center"]), n = vec(shape["normal"]).normalized();
      const double r = shape["radius"];
      const Vec3 u = n.unitOrthogonal(), v = n.cross(u);
      const int k = 128;
      for (int t = 0; t < k; ++t) {
        const double a0 = 2 * std::numbers::pi * t / k, a1 = 2 * std::numbers::pi * (t + 1) / k;
        add(name, {c, c + r * (std::cos(a0) * u + std::sin(a0) * v),
                   c + r * (std::cos(a1) * u + std::sin(a1) * v)});
      }
    }
  }
};

CaseScene sceneOf(const json& c) {
  CaseScene s;
  s.scene.materials.push_back({"grey", Rgb::Constant(0.5), Rgb::Constant(1.0)});
  const json& g = c["geometry"];
  if (g["type"] == "enclosure") {
    for (const json& name : c["face_order"]) s.addShape(name, g["faces"][name.get<std::string>()]);
    return s;
  }
  s.addShape("source", g["source"]);
  s.addShape("receiver", g["receiver"]);
  if (g.contains("occluders"))
    for (const json& o : g["occluders"]) s.addShape("occluder", o);
  return s;
}

// F between two surfaces of the meshed scene.
double groupFormFactor(const Scene& scene, const Mesh& mesh, const FormFactorMatrix& F, int from, int to) {
  auto surfaceOf = [&](std::size_t e) { return scene.patches[mesh.elements[e].patch].surface; };
  double area = 0, sum = 0;
  for (std::size_t a = 0; a < mesh.size(); ++a) {
    if (surfaceOf(a) != from) continue;
    area += mesh.elements[a].area;
    for (std::size_t b = 0; b < mesh.size(); ++b)
      if (surfaceOf(b) == to) sum += mesh.elements[a].area * F(a, b);
  }
  return sum / area;
}

struct MethodSetting {
  const char* method;
  int subdivide;  // elements per patch edge (the centroid methods need a finer mesh than the case's)
  FormFactorOptions options;
};

// What each method must reach, and why:
//  - raycast, 1024 stratified points per pair: without occluders a stratified quadrature of Lambert's
//    bounded point formula (errors ~N^-3/4 next to a shared edge, far smaller elsewhere), 3e-3 absolute; with
//    the occluder the hidden-kernel term is a plain Monte Carlo estimate, sigma = 3e-3 at 1024 samples
//    (measured over 8 seeds: 0.0942 .. 0.1030 around 0.0995), 5 sigma.
//  - montecarlo, 100,000 cosine rays from each element: binomial, sigma = sqrt(F (1 - F) / N) <= 1.6e-3 per
//    patch (over k source patches, / sqrt k); 5 sigma.
//  - hemicube 256^2 at the centroids of 16 x 16 elements per patch: the centroid rule's error is O(h^2) away
//    from edges and O(h) next to a shared edge (tri_share_edge, the hinge, the cube's corners), ~1e-2 at
//    h = 1/16; pixel aliasing adds ~1e-3. 1.5e-2 absolute.
//  - nusselt (16 segments per arc) at the same centroids: the same centroid error, no aliasing; 1.5e-2.
//  - analytic-visibility, 1024 rays: exact (1e-9) without occluders; with them it multiplies the exact
//    unoccluded F by the fraction of rays that get through, which weights the hidden part of the receiver by
//    its area instead of its kernel: a bias, -0.0125 here (0.0870 against 0.0995, 12.5 %), that no number of
//    rays removes. 2e-2 for the occluded case, and the bias itself is asserted.
//  - quadrature at tolerance 1e-6: within its tolerance everywhere, the occluded case included (the hidden
//    part is clipped per point, not sampled).
//  - hybrid, 64 rays per 1 % of F: every case is one element each and closer than 3 radii, so the unoccluded
//    value is the exact one (1e-9); the occluder's part is the raycast estimate at its cap of 1024 rays, as
//    above (measured 0.0963 against 0.0995), 1.5e-2.
std::vector<MethodSetting> settings() {
  std::vector<MethodSetting> out;
  FormFactorOptions o;
  o.samples = 1024;
  out.push_back({"raycast", 1, o});
  out.push_back({"analytic-visibility", 1, o});
  o.samples = 100000;
  out.push_back({"montecarlo", 1, o});
  o = {};
  o.hemicubeResolution = 256;
  out.push_back({"hemicube", 16, o});
  o = {};
  o.samples = 16;
  out.push_back({"nusselt", 16, o});
  o = {};
  o.samples = 64;
  out.push_back({"hybrid", 1, o});
  o = {};
  o.tolerance = 1e-6;
  out.push_back({"quadrature", 1, o});
  return out;
}

double toleranceFor(const std::string& method, double value, bool occluded, int sourcePatches) {
  if (method == "raycast") return occluded ? 1.5e-2 : 3e-3;
  if (method == "montecarlo") return 5 * std::sqrt(value * (1 - value) / (100000.0 * sourcePatches)) + 1e-9;
  if (method == "analytic-visibility") return occluded ? 2e-2 : 1e-9;
  if (method == "hybrid") return occluded ? 1.5e-2 : 1e-9;
  if (method == "quadrature") return 1e-6;  // its requested absolute tolerance, occluded or not
  return 1.5e-2;                            // hemicube, nusselt
}

TEST(ReferenceCases, EveryApproximateMethodWithinItsConvergenceBound) {
  std::ifstream in(test::dataPath("refdata/formfactors.json"));
  const json reference = json::parse(in);
  int checked = 0;
  for (const MethodSetting& setting : settings()) {
    for (const json& c : reference["cases"]) {
      const std::string id = c["id"];
      SCOPED_TRACE(std::string(setting.method) + " " + id);
      const bool disk = c["geometry"]["type"] == "disk_to_disk";
      if (disk && setting.subdivide > 1) continue;
      // A differential source as a tiny square: 1.5e-9 off next to the horizon (dA_perpendicular), so 1e-7
      // relative there.
      const bool differential = c["geometry"]["type"] == "differential_to_polygon";
      const double polygonAllowance = disk ? 3e-4 : differential ? 1e-7 * c["value"].get<double>() : 0.0;
      const CaseScene cs = sceneOf(c);
      MeshOptions meshOptions;
      if (setting.subdivide > 1) {
        meshOptions.mode = MeshOptions::Mode::Count;
        meshOptions.count = setting.subdivide;
      }
      const Mesh mesh = buildMesh(cs.scene, meshOptions);
      FormFactorStats stats;
      const FormFactorMatrix F =
          makeFormFactorMethod(setting.method)->compute(mesh, setting.options, noProgress(), stats);
      const bool occluded = c["geometry"].contains("occluders");
      int sourcePatches = 0;
      for (const Patch& p : cs.scene.patches) sourcePatches += p.surface == 0 ? 1 : 0;
      if (c["geometry"]["type"] == "enclosure") {
        for (std::size_t i = 0; i < 6; ++i)
          for (std::size_t j = 0; j < 6; ++j) {
            const double expected = c["F_matrix"][i][j];
            EXPECT_NEAR(groupFormFactor(cs.scene, mesh, F, static_cast<int>(i), static_cast<int>(j)),
                        expected, toleranceFor(setting.method, expected, false, 1))
                << i << " -> " << j;
          }
      } else {
        // The Nusselt analog projects the whole receiver (it is the lesson's picture of Lambert's formula,
        // occluders ignored): with an occluder it must give the unoccluded value.
        const bool ignoresOccluders = std::string(setting.method) == "nusselt";
        const double value =
            occluded && ignoresOccluders ? c["unoccluded_value"].get<double>() : c["value"].get<double>();
        const double got = groupFormFactor(cs.scene, mesh, F, cs.group.at("source"), cs.group.at("receiver"));
        EXPECT_NEAR(got, value,
                    toleranceFor(setting.method, value, occluded, sourcePatches) + polygonAllowance);
        if (occluded && std::string(setting.method) == "analytic-visibility") {
          EXPECT_GT(std::abs(got - value), 5e-3)
              << "the visible-fraction bias is gone: update the comment above";
        }
        if (c.contains("reciprocal_value") && !(occluded && ignoresOccluders)) {
          const double back = c["reciprocal_value"];
          int receiverPatches = 0;
          for (const Patch& p : cs.scene.patches) receiverPatches += p.surface == 1 ? 1 : 0;
          EXPECT_NEAR(groupFormFactor(cs.scene, mesh, F, cs.group.at("receiver"), cs.group.at("source")),
                      back, toleranceFor(setting.method, back, occluded, receiverPatches) + polygonAllowance);
        }
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, 7 * 14 - 2);  // the centroid methods skip the disks
}

}  // namespace
}  // namespace rt
