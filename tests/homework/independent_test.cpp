// Each topic's key against an independent computation in the program, for 200 seeds: the core's contour
// integral and Nusselt projection for form factors, its hemicube for delta form factors, its kernel for
// ray-cast samples, its assembly, gathering, shooting, Neumann-series and direct solvers, its spectral
// radius, its luminance, and the viewer's display pipeline. The tests read only what a student gets: the
// scene file, the data files and the numbers the statement was written from.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/assembly.h"
#include "core/basis/linear_basis.h"
#include "core/brdf.h"
#include "core/formfactor/analytic.h"
#include "core/formfactor/hemicube.h"
#include "core/formfactor/nusselt.h"
#include "core/formfactor/sampling.h"
#include "core/io/scene_loader.h"
#include "core/radiometry.h"
#include "core/raytrace/ray_cost.h"
#include "core/refine/discontinuity.h"
#include "core/refine/refine.h"
#include "core/solvers/bounces_solver.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/gathering_solvers.h"
#include "core/solvers/shooting_solvers.h"
#include "homework/topic_table.h"
#ifdef RT_HAVE_VIZ
#include "viz/display_pipeline.h"
#endif

namespace rt::homework {
namespace {

constexpr int kSeeds = 200;

double answer(const Exercise& e, const std::string& id) {
  const Question* q = e.find(id);
  EXPECT_NE(q, nullptr) << e.topic << " has no question " << id;
  return q ? q->answer : 0.0;
}

const Eigen::MatrixXd& data(const Exercise& e, const std::string& name) {
  for (const DataFile& d : e.data)
    if (d.name == name) return d.matrix;
  ADD_FAILURE() << e.topic << " has no data file " << name;
  static const Eigen::MatrixXd empty;
  return empty;
}

template <typename F>
void forEachVariant(const char* topic, F&& check) {
  const Topic* t = findTopic(topic);
  ASSERT_NE(t, nullptr);
  for (int seed = 1; seed <= kSeeds; ++seed) check(generateExercise(*t, static_cast<std::uint64_t>(seed), 2));
}

// The key's answer is within a small part of its own tolerance of the program's value.
#define EXPECT_AGREES(e, id, program, share)                             \
  EXPECT_NEAR(answer(e, id), program, (share) * (e).find(id)->tolerance) \
      << (e).topic << " seed " << (e).seed << " " << id

TEST(HomeworkIndependent, RectanglesAgreeWithTheContourIntegral) {
  forEachVariant("rectangles", [](const Exercise& e) {
    const Scene s = parseSceneJson(e.sceneJson);
    ASSERT_EQ(s.patches.size(), 2u);
    const double F12 = polygonToPolygonFormFactor(s.patches[0].vertices, s.patches[1].vertices);
    const double F21 = polygonToPolygonFormFactor(s.patches[1].vertices, s.patches[0].vertices);
    EXPECT_AGREES(e, "F12", F12, 0.1);
    EXPECT_AGREES(e, "F21", F21, 0.1);
  });
}

TEST(HomeworkIndependent, NusseltAgreesWithTheProjectionAndLambert) {
  forEachVariant("nusselt", [](const Exercise& e) {
    const Scene s = parseSceneJson(e.sceneJson);
    const Polygon& rect = s.patches[1].vertices;
    const Vec3 o = Vec3::Zero(), n(0, 0, 1);
    const double projected = nusseltFormFactor(o, n, rect.data(), static_cast<int>(rect.size()), 512);
    EXPECT_AGREES(e, "F", pointToPolygonFormFactor(o, n, rect), 0.01);
    EXPECT_AGREES(e, "F", projected, 0.2);
    EXPECT_AGREES(e, "disk", std::numbers::pi * projected, 0.2);
  });
}

TEST(HomeworkIndependent, ClosureAgreesWithTheContourIntegral) {
  forEachVariant("closure", [](const Exercise& e) {
    const Scene s = parseSceneJson(e.sceneJson);
    ASSERT_EQ(s.patches.size(), 6u);
    auto F = [&](int i, int j) {
      return polygonToPolygonFormFactor(s.patches[i - 1].vertices, s.patches[j - 1].vertices);
    };
    // The given values are rounded to 4 decimals; the derived ones inherit a few 1e-4.
    EXPECT_NEAR(answer(e, "F15"), F(1, 5), 3e-4);
    EXPECT_NEAR(answer(e, "F51"), F(5, 1), 1e-3);
    EXPECT_NEAR(answer(e, "F31"), F(3, 1), 1e-3);
    EXPECT_NEAR(answer(e, "F35"), F(3, 5), 1e-3);
  });
}

TEST(HomeworkIndependent, HemicubeAgreesWithTheProgramsHemicube) {
  forEachVariant("hemicube", [](const Exercise& e) {
    const int res = static_cast<int>(e.given.at("resolution"));
    const double p = 2.0 / res;
    const auto& top = deltaFormFactors(res, HemicubeFace::Top);
    const int col = static_cast<int>(std::floor((e.given.at("x") + 1) / p));
    const int row = static_cast<int>(std::floor((e.given.at("y") + 1) / p));
    EXPECT_AGREES(e, "dTop", top[static_cast<std::size_t>(row * res + col)], 1.0);
    // Face +u: across = y, up = z from the horizon, rows of height 1 / ceil(res / 2) = p.
    const auto& side = deltaFormFactors(res, HemicubeFace::PlusU);
    const int sc = static_cast<int>(std::floor((e.given.at("side_y") + 1) / p));
    const int sr = static_cast<int>(std::floor(e.given.at("side_z") / p));
    EXPECT_AGREES(e, "dSide", side[static_cast<std::size_t>(sr * res + sc)], 1.0);
    // The footprint: the program's hemicube, rendered from the element's centre.
    const Scene scene = parseSceneJson(e.sceneJson);
    const Mesh mesh = buildMesh(scene);
    const HemicubeFaces faces = renderHemicube(mesh, 0, res);
    std::vector<double> rowF(mesh.size(), 0.0);
    accumulateHemicubeRow(faces, rowF.data());
    EXPECT_AGREES(e, "F", rowF[1], 1.0);
    int pixels = 0;
    for (int v : faces.faces[0].element) pixels += v == 1;
    EXPECT_EQ(answer(e, "pixels"), pixels) << "seed " << e.seed;
  });
}

TEST(HomeworkIndependent, RaycastAgreesWithTheProgramsKernelAndSampling) {
  int outside = 0, lineVariants = 0;
  forEachVariant("raycast", [&](const Exercise& e) {
    const Scene s = parseSceneJson(e.sceneJson);
    const Eigen::MatrixXd& table = data(e, "samples");
    const auto& g = e.given;
    const double exact = polygonToPolygonFormFactor(s.patches[0].vertices, s.patches[1].vertices);
    if (g.count("lines")) {
      // Local lines: the core's cosine-distributed direction, followed to j's plane.
      ++lineVariants;
      int hits = 0;
      for (Eigen::Index k = 0; k < table.rows(); ++k) {
        const Vec3 x(g.at("a") * table(k, 0), g.at("b") * table(k, 1), 0);
        const Vec3 d = cosineDirection(s.patches[0].normal, table(k, 2), table(k, 3));
        const Vec3 p = x + (g.at("h") / d.z()) * d;
        const bool hit =
            p.x() > g.at("shift") && p.x() < g.at("shift") + g.at("w") && p.y() > 0 && p.y() < g.at("c");
        hits += hit;
        if (k == 0) {
          EXPECT_EQ(answer(e, "hit1"), hit ? 1.0 : 0.0) << "seed " << e.seed;
        }
      }
      EXPECT_EQ(answer(e, "hits"), hits) << "seed " << e.seed;
      EXPECT_AGREES(e, "F", hits / static_cast<double>(table.rows()), 0.01);
      outside += std::abs(answer(e, "F") - exact) > 3 * answer(e, "SE");
      return;
    }
    const double Aj = s.patches[1].area;
    double sum = 0;
    for (Eigen::Index k = 0; k < table.rows(); ++k) {
      const Vec3 x(g.at("a") * table(k, 0), g.at("b") * table(k, 1), 0);
      const Vec3 y(g.at("shift") + g.at("w") * table(k, 2), g.at("c") * table(k, 3), g.at("h"));
      const double f = Aj * pointToPointKernel(x, s.patches[0].normal, y, s.patches[1].normal);
      if (k == 0) {
        EXPECT_AGREES(e, "f1", f, 0.01);
      }
      sum += f;
    }
    EXPECT_AGREES(e, "F", sum / static_cast<double>(table.rows()), 0.01);
    // The estimate scatters about the exact F by about its standard error.
    outside += std::abs(answer(e, "F") - exact) > 3 * answer(e, "SE");
  });
  EXPECT_GT(lineVariants, kSeeds / 4);
  EXPECT_LE(outside, kSeeds / 10);
}

RadiositySystem systemOf(const Exercise& e, FormFactorMatrix& F) {
  F = data(e, "F");
  RadiositySystem system;
  system.F = &F;
  const Eigen::VectorXd rho = data(e, "rho"), E = data(e, "E");
  system.reflectance = rho.replicate(1, 3);
  system.emission = E.replicate(1, 3);
  system.areas = data(e, "L");
  return system;
}

TEST(HomeworkIndependent, AssembledKAgreesWithTheCoresAssembly) {
  forEachVariant("assemble-k", [](const Exercise& e) {
    const Eigen::MatrixXd K = assembleDense(data(e, "F"), data(e, "rho"));
    for (Eigen::Index i = 0; i < K.rows(); ++i)
      for (Eigen::Index j = 0; j < K.cols(); ++j)
        EXPECT_AGREES(e, "K" + std::to_string(i + 1) + std::to_string(j + 1), K(i, j), 1e-6);
  });
}

TEST(HomeworkIndependent, SweepsAgreeWithTheCoresSolvers) {
  forEachVariant("jacobi-gauss-seidel", [](const Exercise& e) {
    FormFactorMatrix F;
    const RadiositySystem system = systemOf(e, F);
    SolverOptions options;
    options.tolerance = 0;
    options.maxIterations = 2;
    for (const char* which : {"J", "G"}) {
      std::vector<IterationRecord> history;
      RgbField B;
      const IterationSink sink = [&](IterationRecord r) { history.push_back(std::move(r)); };
      which[0] == 'J' ? jacobi(system, B, options, sink) : gaussSeidel(system, B, options, sink);
      ASSERT_EQ(history.size(), 2u);
      for (int k = 0; k < 2; ++k)
        for (Eigen::Index i = 0; i < B.rows(); ++i)
          EXPECT_AGREES(e, which + std::to_string(k + 1) + "[" + std::to_string(i + 1) + "]",
                        history[k].B(i, 0), 1e-6);
    }
    RgbField exact;
    ASSERT_EQ(directSolve(system, exact, {}), SolverStatus::Success);
    for (Eigen::Index i = 0; i < exact.rows(); ++i)
      EXPECT_AGREES(e, "B[" + std::to_string(i + 1) + "]", exact(i, 0), 1e-6);
  });
}

TEST(HomeworkIndependent, ShotsAgreeWithTheCoresSouthwell) {
  forEachVariant("southwell", [](const Exercise& e) {
    FormFactorMatrix F;
    const RadiositySystem system = systemOf(e, F);
    SolverOptions options;
    options.tolerance = 0;
    options.maxIterations = 3;
    options.residualEvery = 1;
    std::vector<IterationRecord> history;
    RgbField B;
    southwell(system, B, options, [&](IterationRecord r) { history.push_back(std::move(r)); });
    ASSERT_GE(history.size(), 3u);
    const std::size_t first = history.size() - 3;  // a record of the start may come first
    for (int k = 0; k < 3; ++k) {
      const IterationRecord& r = history[first + k];
      const std::string shot = std::to_string(k + 1);
      EXPECT_EQ(answer(e, "shooter" + shot), r.shooter + 1) << "seed " << e.seed;
      for (Eigen::Index i = 0; i < r.B.rows(); ++i)
        EXPECT_AGREES(e, "B" + shot + "[" + std::to_string(i + 1) + "]", r.B(i, 0), 1e-6);
      EXPECT_AGREES(e, "unshot" + shot, r.unshotPower / 3, 1e-6);  // the core sums three equal channels
    }
  });
}

TEST(HomeworkIndependent, StochasticJacobiAgreesWithItsLinesAndTheCoresJacobiSweep) {
  forEachVariant("stochastic-jacobi", [](const Exercise& e) {
    FormFactorMatrix F;
    const RadiositySystem system = systemOf(e, F);
    const Eigen::MatrixXd& lines = data(e, "lines");
    const Eigen::VectorXd& L = system.areas;
    const Eigen::VectorXd E = system.emission.col(0), rho = system.reflectance.col(0);
    const Eigen::VectorXd power = E.cwiseProduct(L);
    const auto n = L.size();
    // The lines of the table, drawn again with the running sums the statement describes.
    Eigen::VectorXd counts = Eigen::VectorXd::Zero(n);
    for (Eigen::Index k = 0; k < lines.rows(); ++k) {
      Eigen::Index from = 0, to = 0;
      for (double sum = power[0] / power.sum(); lines(k, 0) >= sum; sum += power[from] / power.sum()) ++from;
      for (double sum = F(from, 0); lines(k, 1) >= sum; sum += F(from, to)) ++to;
      ASSERT_LT(to, n) << "seed " << e.seed;
      counts[to] += 1;
    }
    const double perRay = power.sum() / static_cast<double>(lines.rows());
    EXPECT_AGREES(e, "perRay", perRay, 1e-6);
    for (Eigen::Index j = 0; j < n; ++j) {
      const std::string side = "[" + std::to_string(j + 1) + "]";
      EXPECT_EQ(answer(e, "count" + side), counts[j]) << "seed " << e.seed;
      EXPECT_AGREES(e, "B1" + side, E[j] + rho[j] * counts[j] * perRay / L[j], 1e-6);
    }
    // The deterministic sweep is the core's Jacobi sweep from E (the rounded F's reciprocity is good to far
    // less than the tolerance).
    SolverOptions options;
    options.tolerance = 0;
    options.maxIterations = 1;
    RgbField B;
    jacobi(system, B, options);
    const int asked = static_cast<int>(e.given.at("asked"));
    EXPECT_AGREES(e, "exact", B(asked - 1, 0), 0.5);
  });
}

TEST(HomeworkIndependent, BouncesAgreeWithTheNeumannSeriesAndTheDirectSolver) {
  forEachVariant("bounces", [](const Exercise& e) {
    FormFactorMatrix F;
    const RadiositySystem system = systemOf(e, F);
    SolverOptions options;
    options.tolerance = 0;
    options.maxIterations = 5;
    std::vector<RgbField> terms;
    RgbField B;
    neumannSeries(system, B, options, {}, &terms);
    ASSERT_GE(terms.size(), 5u);
    for (Eigen::Index i = 0; i < B.rows(); ++i)
      EXPECT_AGREES(e, "T1[" + std::to_string(i + 1) + "]", terms[1](i, 0), 1e-6);
    RgbField exact;
    directSolve(system, exact, {});
    const Eigen::VectorXd L = data(e, "L");
    const double total = exact.col(0).dot(L);
    // Which bounce: the one whose power the key gives.
    int k = 1;
    for (int m = 1; m <= 3; ++m)
      if (std::abs(terms[m].col(0).dot(L) - answer(e, "P")) <
          std::abs(terms[k].col(0).dot(L) - answer(e, "P")))
        k = m;
    EXPECT_AGREES(e, "P", terms[k].col(0).dot(L), 1e-6);
    EXPECT_AGREES(e, "share", terms[k].col(0).dot(L) / total, 1e-6);
  });
}

TEST(HomeworkIndependent, SpectralRadiusAgreesWithTheCoresPowerIteration) {
  forEachVariant("spectral-radius", [](const Exercise& e) {
    const SpectralRadiusEstimate r = spectralRadius(data(e, "F"), data(e, "rho"));
    ASSERT_TRUE(r.converged);
    EXPECT_AGREES(e, "r", r.value, 0.01);
    const double tau = std::pow(10.0, -e.given.at("exponent"));
    EXPECT_EQ(answer(e, "m"), std::ceil(std::log(tau) / std::log(r.value))) << "seed " << e.seed;
  });
}

TEST(HomeworkIndependent, SubdivisionAgreesWithTheCoresLuminance) {
  forEachVariant("subdivision", [](const Exercise& e) {
    const Eigen::MatrixXd& el = data(e, "elements");
    double w = 0, a = 0, jump = 0;
    std::vector<double> Y;
    for (Eigen::Index i = 0; i < el.rows(); ++i) Y.push_back(luminance(el.row(i).tail<3>()));
    for (Eigen::Index i = 0; i < el.rows(); ++i)
      if (i != 4) w += el(i, 0) * Y[i], a += el(i, 0);
    for (int j = 1; j <= 3; ++j) jump = std::max(jump, std::abs(Y[0] - Y[j]));
    const double threshold = e.given.at("tolerance") * w / a;
    EXPECT_AGREES(e, "Y1", Y[0], 0.01);
    EXPECT_AGREES(e, "mean", w / a, 0.01);
    EXPECT_AGREES(e, "threshold", threshold, 0.01);
    EXPECT_AGREES(e, "jump", jump, 0.01);
    const bool split = jump > threshold && e.given.at("edge") >= 2 * e.given.at("min_edge");
    EXPECT_EQ(answer(e, "split"), split ? 1.0 : 0.0);
  });
}

TEST(HomeworkIndependent, IrradianceAgreesWithTheExactSolidAngle) {
  forEachVariant("irradiance", [](const Exercise& e) {
    // The patch as the statement describes it: centre r along +z, normal turned by the tilt from the line to
    // the lamp at the origin.
    const double r = e.given.at("distance"), side = e.given.at("side");
    const double t = e.given.at("tilt") * std::numbers::pi / 180;
    const Vec3 centre(0, 0, r), n(0, std::sin(t), -std::cos(t)), u(1, 0, 0), v = n.cross(u);
    const Polygon patch{centre - side / 2 * (u + v), centre + side / 2 * (u - v), centre + side / 2 * (u + v),
                        centre - side / 2 * (u - v)};
    const double omega = polygonSolidAngle(Vec3::Zero(), patch);
    const double intensity = e.given.at("power") / (4 * std::numbers::pi);
    EXPECT_AGREES(e, "omega", omega, 0.6);
    EXPECT_AGREES(e, "I", intensity, 0.01);
    EXPECT_AGREES(e, "P", intensity * omega, 0.6);
    EXPECT_AGREES(e, "H", intensity * omega / (side * side), 0.6);
  });
}

TEST(HomeworkIndependent, LinearElementAgreesWithTheCoresBasis) {
  forEachVariant("linear-element", [](const Exercise& e) {
    const double a = e.given.at("a"), b = e.given.at("b");
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}};
    Element element;
    element.vertices = {0, 1, 2, 3};
    element.patch = 0;
    element.normal = Vec3(0, 0, 1);
    element.centroid = Vec3(a / 2, b / 2, 0);
    element.area = a * b;
    mesh.elements.push_back(element);
    const LinearBasis basis = buildLinearBasis(mesh);
    RgbField nodal(4, 3);
    for (int k = 0; k < 4; ++k) nodal.row(k).setConstant(e.given.at("b" + std::to_string(k + 1)));
    const double u = e.given.at("x") / a, v = e.given.at("y") / b;
    const int corner = static_cast<int>(e.given.at("asked")) - 1;
    double phi[4];
    ElementMap(mesh, 0).shape(u, v, phi);
    EXPECT_AGREES(e, "phi", phi[corner], 0.01);
    EXPECT_AGREES(e, "B", basis.valueAt(mesh, nodal, 0, u, v)[0], 0.01);
    EXPECT_AGREES(e, "average", basis.elementAverages(nodal)(0, 0), 0.01);
    EXPECT_AGREES(e, "weight", basis.cornerWeight[static_cast<std::size_t>(corner)], 0.01);
  });
}

TEST(HomeworkIndependent, RayTreeAgreesWithTheCostFormula) {
  forEachVariant("ray-tree", [](const Exercise& e) {
    RayCostInputs in;
    in.pixels = static_cast<std::int64_t>(e.given.at("width") * e.given.at("height"));
    in.pixelSamples = static_cast<int>(e.given.at("samples"));
    in.lights = static_cast<int>(e.given.at("lights"));
    in.shadowRays = static_cast<int>(e.given.at("shadow"));
    in.depth = static_cast<int>(e.given.at("depth"));
    in.branching = static_cast<int>(e.given.at("branching"));
    const RayCost cost = whittedRayCost(in);
    EXPECT_EQ(answer(e, "nodes"), cost.treeNodes);
    EXPECT_EQ(answer(e, "shadow"), cost.treeNodes * in.lights * in.shadowRays);
    EXPECT_EQ(answer(e, "perPixel"), cost.perPixel);
    EXPECT_EQ(answer(e, "total"), cost.total);
    EXPECT_AGREES(e, "seconds", cost.total / (e.given.at("rate") * 1e6), 0.01);
  });
}

TEST(HomeworkIndependent, DenseCostAgreesWithTheCoresMatrix) {
  forEachVariant("dense-cost", [](const Exercise& e) {
    const double n = e.given.at("patches") * e.given.at("split") * e.given.at("split");
    EXPECT_EQ(answer(e, "n"), n);
    // The core stores F as a dense matrix of this scalar: n^2 of them.
    const double entry = static_cast<double>(sizeof(FormFactorMatrix::Scalar));
    EXPECT_AGREES(e, "GB", entry * n * n / 1e9, 0.01);
    const double fits = answer(e, "fits"), memory = e.given.at("memory") * 1e9;
    EXPECT_LE(entry * fits * fits, memory);
    EXPECT_GT(entry * (fits + 1) * (fits + 1), memory);
    const double refined = n * std::pow(e.given.at("refine"), 2);
    EXPECT_EQ(answer(e, "growth"), refined * refined / (n * n));
    EXPECT_AGREES(e, "sweepSeconds", 3 * n * n / (e.given.at("flopRate") * 1e9), 0.01);
  });
}

TEST(HomeworkIndependent, PhongAgreesWithTheCoreBrdf) {
  forEachVariant("phong", [](const Exercise& e) {
    // The lamp at theta_i on the -x side, the viewer at theta_o on the +x side, in the x-z plane.
    const double toRadians = std::numbers::pi / 180;
    const Vec3 wi = directionAt(e.given.at("incidence") * toRadians, std::numbers::pi);
    const Vec3 wo = directionAt(e.given.at("view") * toRadians, 0);
    Brdf phong;
    phong.model = BrdfModel::Phong;
    phong.diffuse = e.given.at("kd");
    phong.specular = e.given.at("ks");
    phong.exponent = e.given.at("q");
    const double f = evaluateBrdf(phong, wi, wo);
    EXPECT_AGREES(e, "alpha", std::acos(mirrorDirection(wi).dot(wo)) / toRadians, 0.1);
    EXPECT_AGREES(e, "f", f, 0.01);
    EXPECT_AGREES(e, "fs", f - phong.diffuse / std::numbers::pi, 0.01);
    EXPECT_AGREES(e, "L", f * e.given.at("H"), 0.01);
  });
}

// A disc of radius R, `sides` corners, centred on the z axis at the height h, facing down (CCW seen from
// below).
Polygon discFacingDown(double R, double h, int sides) {
  Polygon disc;
  for (int k = 0; k < sides; ++k) {
    const double t = -2 * std::numbers::pi * k / sides;
    disc.emplace_back(R * std::cos(t), R * std::sin(t), h);
  }
  return disc;
}

TEST(HomeworkIndependent, ReflectionEquationAgreesWithLambertsFormulaForTheLamp) {
  forEachVariant("reflection-equation", [](const Exercise& e) {
    const double R = e.given.at("radius"), h = e.given.at("height"), L = e.given.at("radiance");
    const int sides = 720;
    // The inscribed polygon's area is short of the disc's by sin(2 pi/n) / (2 pi/n): scale it back.
    const double step = 2 * std::numbers::pi / sides;
    const double F = pointToPolygonFormFactor(Vec3::Zero(), Vec3(0, 0, 1), discFacingDown(R, h, sides)) /
                     (std::sin(step) / step);
    const double H = std::numbers::pi * L * F, rho = e.given.at("rho");
    EXPECT_AGREES(e, "s2", F, 0.2);
    EXPECT_AGREES(e, "H", H, 0.2);
    EXPECT_AGREES(e, "Lr", rho * H / std::numbers::pi, 0.2);
    EXPECT_AGREES(e, "B", rho * H, 0.2);
  });
}

TEST(HomeworkIndependent, HierarchicalOracleAgreesWithTheCoresKernelAndSplittingRule) {
  forEachVariant("hierarchical-oracle", [](const Exercise& e) {
    const double a = e.given.at("a"), b = e.given.at("b"), h = e.given.at("height"), x = e.given.at("offset");
    const Vec3 cp(0, 0, 0), cq(x, 0, h), up(0, 0, 1), down(0, 0, -1);
    // A node shrunk about its centre by delta: its point-to-polygon F over delta^2 is the small-node
    // estimate.
    const double delta = 1e-3;
    auto square = [](const Vec3& c, double side, bool facingUp) {
      const double s = side / 2;
      return facingUp
                 ? Polygon{c + Vec3(-s, -s, 0), c + Vec3(s, -s, 0), c + Vec3(s, s, 0), c + Vec3(-s, s, 0)}
                 : Polygon{c + Vec3(-s, -s, 0), c + Vec3(-s, s, 0), c + Vec3(s, s, 0), c + Vec3(s, -s, 0)};
    };
    const double Fpq = pointToPolygonFormFactor(cp, up, square(cq, b * delta, false)) / (delta * delta);
    const double Fqp = pointToPolygonFormFactor(cq, down, square(cp, a * delta, true)) / (delta * delta);
    EXPECT_AGREES(e, "Fpq", Fpq, 0.05);
    EXPECT_AGREES(e, "Fqp", Fqp, 0.05);
    // The core's rule (refine/hierarchical_radiosity.cpp): split the receiver p when F_qp >= F_pq.
    const bool splitReceiver = pointToPolygonFormFactor(cq, down, square(cp, a, true)) >=
                               pointToPolygonFormFactor(cp, up, square(cq, b, false));
    EXPECT_EQ(answer(e, "split"), splitReceiver ? 1.0 : 2.0) << "seed " << e.seed;
    // The children, each with its own centre.
    const double side = splitReceiver ? a : b, other = splitReceiver ? b : a;
    const Vec3 splitCentre = splitReceiver ? cp : cq, otherCentre = splitReceiver ? cq : cp;
    const Vec3 splitNormal = splitReceiver ? up : down, otherNormal = splitReceiver ? down : up;
    int linked = 0;
    for (int c = 0; c < 4; ++c) {
      const Vec3 child =
          splitCentre + Vec3((c & 1) ? side / 4 : -side / 4, (c & 2) ? side / 4 : -side / 4, 0);
      const double toOther =
          pointToPolygonFormFactor(child, splitNormal, square(otherCentre, other * delta, !splitReceiver));
      const double toChild =
          pointToPolygonFormFactor(otherCentre, otherNormal, square(child, side / 2 * delta, splitReceiver));
      linked += std::max(toOther, toChild) / (delta * delta) < e.given.at("epsilon");
    }
    EXPECT_EQ(answer(e, "linked"), linked) << "seed " << e.seed;
  });
}

// The scene file handed out: the core's critical segments on the floor that cross the section y = 0 are the
// four lines of the key; the visible width is counted by rays traced forwards from the floor point to points
// of the light, hidden when they pass through the table.
TEST(HomeworkIndependent, DiscontinuityAgreesWithTheCoresCriticalSegments) {
  forEachVariant("discontinuity", [](const Exercise& e) {
    const Scene s = parseSceneJson(e.sceneJson);
    ASSERT_EQ(s.patches.size(), 3u);
    std::vector<double> lines;
    for (const CriticalSegment& c : criticalSegments(s, 0, 1e-9)) {
      if (std::min(c.a.y(), c.b.y()) > 0 || std::max(c.a.y(), c.b.y()) < 0) continue;
      EXPECT_NEAR(c.a.x(), c.b.x(), 1e-9) << "seed " << e.seed << ": a line across y = 0 runs along y";
      if (std::none_of(lines.begin(), lines.end(), [&](double x) { return std::abs(x - c.a.x()) < 1e-9; }))
        lines.push_back(c.a.x());
    }
    std::sort(lines.begin(), lines.end());
    ASSERT_EQ(lines.size(), 4u) << "seed " << e.seed;
    int crossing = 0;
    for (int i = 0; i < 4; ++i) {
      EXPECT_AGREES(e, "x" + std::to_string(i + 1), lines[static_cast<std::size_t>(i)], 0.01);
      crossing += lines[static_cast<std::size_t>(i)] > e.given.at("e0") &&
                  lines[static_cast<std::size_t>(i)] < e.given.at("e1");
    }
    EXPECT_EQ(answer(e, "crossing"), crossing) << "seed " << e.seed;
    const double xp = e.given.at("xp"), l0 = e.given.at("l0"), l1 = e.given.at("l1");
    const double H = e.given.at("H"), h = e.given.at("h"), o0 = e.given.at("o0"), o1 = e.given.at("o1");
    constexpr int kRays = 20000;
    int seen = 0;
    for (int r = 0; r < kRays; ++r) {
      const double l = l0 + (l1 - l0) * (r + 0.5) / kRays;
      const double atTable = xp + (l - xp) * h / H;
      seen += atTable < o0 || atTable > o1;
    }
    EXPECT_AGREES(e, "visible", (l1 - l0) * seen / kRays, 0.5);
    EXPECT_EQ(answer(e, "order"), 1.0) << "parallel edges";
  });
}

TEST(HomeworkIndependent, RandomWalkLengthAgreesWithTheCoresDirectSolution) {
  forEachVariant("random-walk", [](const Exercise& e) {
    // A closed room of three patches (rows of F sum to 1, A_i F_ij = A_j F_ji) with the exercise's rho and a
    // light on patch 1: the power arriving everywhere over the power emitted is the mean number of arrivals.
    Eigen::Vector3d A(1.0, 2.0, 3.0);
    Eigen::Matrix3d exchange;  // A_i F_ij: symmetric, row i sums to A_i
    exchange << 0, 0.4, 0.6, 0.4, 0.6, 1.0, 0.6, 1.0, 1.4;
    const FormFactorMatrix F = A.cwiseInverse().asDiagonal() * exchange;
    for (int i = 0; i < 3; ++i) ASSERT_NEAR(F.row(i).sum(), 1, 1e-12);
    const double rho = e.given.at("rho");
    RadiositySystem system;
    system.F = &F;
    system.reflectance = RgbField::Constant(3, 3, rho);
    system.emission = RgbField::Zero(3, 3);
    system.emission.row(0).setConstant(10);
    system.areas = A;
    RgbField B;
    directSolve(system, B, {});
    double arriving = 0;
    for (int i = 0; i < 3; ++i) arriving += A(i) * (B(i, 0) - system.emission(i, 0)) / rho;
    EXPECT_AGREES(e, "hits", arriving / (A(0) * 10), 0.01);
    EXPECT_AGREES(e, "survive", std::pow(rho, e.given.at("k") - 1), 0.01);
  });
}

TEST(HomeworkIndependent, TwoPassAgreesWithTheNusseltProjectionAndTheLampsExactFormFactor) {
  forEachVariant("two-pass", [](const Exercise& e) {
    const Eigen::MatrixXd& table = data(e, "surfaces");
    const double W = e.given.at("W"), D = e.given.at("D"), H = e.given.at("H"), s = e.given.at("side");
    const double lx = e.given.at("lx"), ly = e.given.at("ly");
    const Vec3 P(e.given.at("px"), e.given.at("py"), 0), n(0, 0, 1);
    const Polygon lamp{Vec3(lx - s / 2, ly - s / 2, H), Vec3(lx - s / 2, ly + s / 2, H),
                       Vec3(lx + s / 2, ly + s / 2, H), Vec3(lx + s / 2, ly - s / 2, H)};
    const std::vector<Polygon> others{{Vec3(0, 0, H), Vec3(0, D, H), Vec3(W, D, H), Vec3(W, 0, H)},
                                      {Vec3(0, 0, 0), Vec3(0, D, 0), Vec3(0, D, H), Vec3(0, 0, H)},
                                      {Vec3(W, 0, 0), Vec3(W, 0, H), Vec3(W, D, H), Vec3(W, D, 0)},
                                      {Vec3(0, 0, 0), Vec3(0, 0, H), Vec3(W, 0, H), Vec3(W, 0, 0)},
                                      {Vec3(0, D, 0), Vec3(W, D, 0), Vec3(W, D, H), Vec3(0, D, H)}};
    // The printed form factors against the Nusselt projection (to their four digits), and the hemisphere
    // closes: lamp, ceiling and walls are everything the floor point sees.
    const double lampF = nusseltFormFactor(P, n, lamp.data(), 4, 512);
    EXPECT_NEAR(table(0, 1), lampF, 6e-4 * lampF);
    double sum = table(0, 1), Hi = 0;
    for (std::size_t j = 0; j < others.size(); ++j) {
      double F = nusseltFormFactor(P, n, others[j].data(), 4, 512);
      if (j == 0) F -= lampF;
      EXPECT_NEAR(table(static_cast<Eigen::Index>(j + 1), 1), F, 6e-5)
          << "seed " << e.seed << " row " << j + 1;
      sum += table(static_cast<Eigen::Index>(j + 1), 1);
      Hi += table(static_cast<Eigen::Index>(j + 1), 0) * table(static_cast<Eigen::Index>(j + 1), 1);
    }
    EXPECT_NEAR(sum, 1.0, 4e-4);
    EXPECT_AGREES(e, "Hi", Hi, 0.01);
    // The small-source direct part against the lamp's exact form factor: within the small-source error,
    // about (side / r)^2 of it.
    const double r2 = (Vec3(lx, ly, H) - P).squaredNorm();
    const double exact = table(0, 0) * pointToPolygonFormFactor(P, n, lamp);
    EXPECT_NEAR(answer(e, "Hd"), exact, exact * s * s / r2) << "seed " << e.seed;
    const double rho = e.given.at("rho");
    EXPECT_AGREES(e, "B", rho * (answer(e, "Hd") + Hi), 0.01);
    EXPECT_AGREES(e, "L", rho * (answer(e, "Hd") + Hi) / std::numbers::pi, 0.01);
  });
}

#ifdef RT_HAVE_VIZ
TEST(HomeworkIndependent, ToneMappingAgreesWithTheDisplayPipeline) {
  forEachVariant("tone-mapping", [](const Exercise& e) {
    viz::DisplaySettings settings;
    settings.exposure = e.given.at("exposure");
    settings.toneMap = e.given.at("reinhard") > 0 ? viz::ToneMap::Reinhard : viz::ToneMap::LinearClamp;
    settings.srgbGamma = true;
    const Eigen::MatrixXd& B = data(e, "B");
    for (Eigen::Index i = 0; i < B.rows(); ++i) {
      const viz::Rgb8 c = viz::displayColour(Rgb::Constant(B(i, 0)), settings);
      EXPECT_EQ(answer(e, "v" + std::to_string(i + 1)), c[0]) << "seed " << e.seed;
    }
  });
}
#endif

}  // namespace
}  // namespace rt::homework
