// Small radiosity systems with known form factors: the closed unit cube (exact F), the same cube with its top
// removed (an open box), two facing plates that see only each other, and random reciprocal enclosures of any
// size. The cubes carry their geometry too (solvers that trace rays need it); the plates and the random
// enclosures have none. Header-only so that core and stress tests share it.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <random>

#include <string>
#include <vector>

#include "core/basis/linear_kernel.h"
#include "core/mesh.h"
#include "core/solvers/radiosity_system.h"
#include "core/solvers/solver.h"

namespace rt::test {

// Exact form factors between faces of a unit cube (Hottel's crossed strings / the analytic parallel and
// perpendicular square formulas): opposite faces and faces sharing an edge. Rows sum to 1.
constexpr double kCubeOpposite = 0.19982489569838738;
constexpr double kCubeAdjacent = 0.20004377607540316;

// Faces 0..5 are -x, +x, -y, +y, -z, +z; 2k and 2k+1 are opposite.
inline FormFactorMatrix cubeFormFactors() {
  FormFactorMatrix F(6, 6);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) F(i, j) = i == j ? 0.0 : (i / 2 == j / 2 ? kCubeOpposite : kCubeAdjacent);
  return F;
}

// The faces of the unit cube as one element each, in the order of cubeFormFactors, facing inward
// (counter-clockwise seen from inside).
inline std::unique_ptr<Mesh> cubeMesh(const std::vector<int>& faces = {0, 1, 2, 3, 4, 5}) {
  auto mesh = std::make_unique<Mesh>();
  for (const int face : faces) {
    const int axis = face / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
    Vec3 inward = Vec3::Zero();
    inward(axis) = face % 2 == 0 ? 1.0 : -1.0;
    Element e;
    e.patch = face;
    const int corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto& corner : corners) {
      Vec3 p = Vec3::Zero();
      p(axis) = face % 2;
      p(u) = corner[0];
      p(v) = corner[1];
      e.vertices.push_back(static_cast<int>(mesh->vertices.size()));
      mesh->vertices.push_back(p);
    }
    const Vec3 a = mesh->vertices[e.vertices[0]], b = mesh->vertices[e.vertices[1]],
               c = mesh->vertices[e.vertices[2]];
    if ((b - a).cross(c - a).dot(inward) < 0) std::swap(e.vertices[1], e.vertices[3]);
    e.normal = inward;
    e.centroid = Vec3::Constant(0.5) - 0.5 * inward;
    e.area = 1.0;
    mesh->elements.push_back(e);
  }
  mesh->vertexElements.resize(mesh->vertices.size());
  for (std::size_t i = 0; i < mesh->elements.size(); ++i)
    for (const int v : mesh->elements[i].vertices) mesh->vertexElements[v].push_back(static_cast<int>(i));
  return mesh;
}

// A system that owns its F and, when it has one, its geometry (RadiositySystem only points to them).
struct OwnedSystem {
  std::unique_ptr<FormFactorMatrix> F;
  std::unique_ptr<Mesh> mesh;
  RadiositySystem system;
  OwnedSystem() = default;
  OwnedSystem(OwnedSystem&&) = default;
  OwnedSystem& operator=(OwnedSystem&&) = default;
  void set(FormFactorMatrix matrix) {
    F = std::make_unique<FormFactorMatrix>(std::move(matrix));
    system.F = F.get();
  }
  void setMesh(std::unique_ptr<Mesh> geometry) {
    mesh = std::move(geometry);
    system.mesh = mesh.get();
  }
};

// Whether solver `name` can run on `system`: a solver that traces rays needs its geometry.
inline bool canSolve(const std::string& name, const RadiositySystem& system) {
  return solverInfo(name).input != SolverInput::Geometry || system.mesh != nullptr;
}

// Closed unit cube, uniform reflectance and emission on every face: B = E / (1 - rho) exactly (the furnace).
inline OwnedSystem furnaceCube(double rho, double emission = 1.0) {
  OwnedSystem s;
  s.set(cubeFormFactors());
  s.setMesh(cubeMesh());
  s.system.areas = Eigen::VectorXd::Ones(6);
  s.system.reflectance = RgbField::Constant(6, 3, rho);
  s.system.emission = RgbField::Constant(6, 3, emission);
  return s;
}

// Closed unit cube with coloured walls and a light on the ceiling (+z): a small Cornell-like box.
inline OwnedSystem colouredCube() {
  OwnedSystem s;
  s.set(cubeFormFactors());
  s.setMesh(cubeMesh());
  s.system.areas = Eigen::VectorXd::Ones(6);
  s.system.reflectance.resize(6, 3);
  s.system.reflectance << 0.63, 0.06, 0.04,  // -x red
      0.15, 0.45, 0.09,                      // +x green
      0.72, 0.72, 0.72,                      // -y white
      0.0, 0.0, 0.0,                         // +y black: gathers nothing
      0.5, 0.5, 0.5,                         // floor
      0.78, 0.78, 0.78;                      // ceiling (emitter)
  s.system.emission = RgbField::Zero(6, 3);
  s.system.emission.row(5) << 10.0, 9.0, 7.0;
  return s;
}

// The coloured cube without its -y face: rows of the faces that saw it sum to 1 - F; light escapes.
// The coloured cube with a linear basis (core/basis/linear_kernel.h): four nodes per face, 24 unknowns, the
// nodes' kernel K in place of F and their weights as areas. No mesh: nothing traces rays through nodes.
inline OwnedSystem colouredCubeLinear() {
  const OwnedSystem cube = colouredCube();
  const LinearBasis basis = buildLinearBasis(*cube.mesh);
  FormFactorStats stats;
  OwnedSystem s;
  s.set(linearKernelMatrix(*cube.mesh, basis, {}, noProgress(), stats));
  const auto m = static_cast<Eigen::Index>(basis.size());
  s.system.areas = basis.weights;
  s.system.reflectance.resize(m, 3);
  s.system.emission.resize(m, 3);
  for (Eigen::Index v = 0; v < m; ++v) {
    s.system.reflectance.row(v) = cube.system.reflectance.row(basis.nodePatch[static_cast<std::size_t>(v)]);
    s.system.emission.row(v) = cube.system.emission.row(basis.nodePatch[static_cast<std::size_t>(v)]);
  }
  return s;
}

inline OwnedSystem openBox() {
  OwnedSystem closed = colouredCube();
  const int keep[5] = {0, 1, 3, 4, 5};
  FormFactorMatrix F(5, 5);
  OwnedSystem s;
  s.system.areas = Eigen::VectorXd::Ones(5);
  s.system.reflectance.resize(5, 3);
  s.system.emission.resize(5, 3);
  for (int a = 0; a < 5; ++a) {
    for (int b = 0; b < 5; ++b) F(a, b) = (*closed.F)(keep[a], keep[b]);
    s.system.reflectance.row(a) = closed.system.reflectance.row(keep[a]);
    s.system.emission.row(a) = closed.system.emission.row(keep[a]);
  }
  s.system.reflectance.row(2) << 0.3, 0.3, 0.3;  // the +y face is no longer black here
  s.set(F);
  s.setMesh(cubeMesh({0, 1, 3, 4, 5}));
  return s;
}

// Two parallel plates that see only each other (F = [0 1; 1 0]): the case where plain power iteration
// oscillates.
inline OwnedSystem facingPlates(double rho) {
  OwnedSystem s;
  FormFactorMatrix F(2, 2);
  F << 0, 1, 1, 0;
  s.set(F);
  s.system.areas = Eigen::VectorXd::Ones(2);
  s.system.reflectance = RgbField::Constant(2, 3, rho);
  s.system.emission = RgbField::Zero(2, 3);
  s.system.emission.row(0) << 1, 1, 1;
  return s;
}

// A random enclosure with n elements: symmetric exchange A_i F_ij = A_j F_ji, row sums <= maxRowSum (=
// maxRowSum for the fullest row), about `fill` of the pairs visible, reflectance in [0.2, 0.8], a few
// emitters.
inline OwnedSystem randomSystem(int n, std::uint64_t seed, double maxRowSum = 0.95, double fill = 0.6) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  OwnedSystem s;
  s.system.areas.resize(n);
  for (int i = 0; i < n; ++i) s.system.areas(i) = 0.5 + 1.5 * uniform(engine);
  Eigen::MatrixXd exchange = Eigen::MatrixXd::Zero(n, n);  // A_i F_ij, symmetric
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (uniform(engine) < fill) exchange(i, j) = exchange(j, i) = uniform(engine);
  FormFactorMatrix F = s.system.areas.cwiseInverse().asDiagonal() * exchange;
  const double largest = F.rowwise().sum().maxCoeff();
  if (largest > 0) F *= maxRowSum / largest;
  s.set(F);
  s.system.reflectance.resize(n, 3);
  s.system.emission = RgbField::Zero(n, 3);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) s.system.reflectance(i, c) = 0.2 + 0.6 * uniform(engine);
  for (int i = 0; i < n; i += 7) s.system.emission.row(i) << 5.0, 4.0, 3.0;
  return s;
}

}  // namespace rt::test
