#include "homework/duct.h"

#include <cmath>
#include <numbers>

#include "homework/scene_text.h"

namespace rt::homework {

std::optional<Duct> drawDuct(Draw& draw, int n, double rhoLo, double rhoHi) {
  Duct d;
  const double start = draw.uniform() * 2 * std::numbers::pi;
  for (int k = 0; k < n; ++k) {
    const double angle = start + 2 * std::numbers::pi * (k + 0.35 * (draw.uniform() - 0.5)) / n;
    const double radius = 0.8 + 0.5 * draw.uniform();
    d.corners.emplace_back(std::round(10 * radius * std::cos(angle)) / 10,
                           std::round(10 * radius * std::sin(angle)) / 10);
  }
  d.length.resize(n);
  for (int i = 0; i < n; ++i) {
    const Vec2 a = d.corners[i], b = d.corners[(i + 1) % n], c = d.corners[(i + 2) % n];
    d.length[i] = (b - a).norm();
    const Vec2 e1 = b - a, e2 = c - b;
    if (d.length[i] < 0.3 || e1.x() * e2.y() - e1.y() * e2.x() < 0.05) return std::nullopt;
  }
  d.F = Eigen::MatrixXd::Zero(n, n);
  auto dist = [&](int a, int b) { return (d.corners[a % n] - d.corners[b % n]).norm(); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (i != j)
        d.F(i, j) = std::round(1e4 * (dist(i, j) + dist(i + 1, j + 1) - dist(i, j + 1) - dist(i + 1, j)) /
                               (2 * d.length[i])) /
                    1e4;
  d.rho.resize(n);
  d.E = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) d.rho[i] = draw.value(rhoLo, rhoHi, 0.05);
  const int light = draw.integer(0, n - 1);
  d.E[light] = draw.integer(2, 10);
  if (draw.uniform() < 0.3) d.E[(light + 1 + draw.integer(0, n - 2)) % n] = draw.integer(1, 5);
  return d;
}

std::string ductStatement(const Duct& d) {
  const int n = static_cast<int>(d.length.size());
  std::string s = "A long duct has a cross-section with " + std::to_string(n) + " sides (corners ";
  for (int i = 0; i < n; ++i)
    s += (i ? ", " : "") + std::string("$(") + num(d.corners[i].x()) + ", " + num(d.corners[i].y()) + ")$";
  s += "; side $i$ runs from corner $i$ to corner $i+1$). Per unit length of duct, the side lengths are $L "
       "= " +
       vectorLatex(d.length, 4) +
       "$, the form factors (crossed strings, rounded) are $F = " + matrixLatex(d.F, 4) +
       "$, the reflectances $\\rho = " + vectorLatex(d.rho) + "$ and the emissions $E = " + vectorLatex(d.E) +
       "$ (data files `F`, `rho`, `E`, `L`).";
  return s;
}

void addDuctData(Exercise& e, const Duct& d) {
  e.data.push_back({"F", d.F});
  e.data.push_back({"rho", d.rho});
  e.data.push_back({"E", d.E});
  e.data.push_back({"L", d.length});
}

Figure ductFigure(const Duct& d) {
  Figure f;
  f.polygon(d.corners, "light");
  const int n = static_cast<int>(d.corners.size());
  Vec2 centre = Vec2::Zero();
  for (const Vec2& c : d.corners) centre += c / n;
  for (int i = 0; i < n; ++i) {
    const Vec2 mid = 0.5 * (d.corners[i] + d.corners[(i + 1) % n]);
    f.label(mid + 0.18 * (mid - centre).normalized(), std::to_string(i + 1));
  }
  f.caption = "Cross-section of the duct; the sides are numbered.";
  return f;
}

void addDuctScene(Exercise& e, const Duct& d) {
  std::vector<NamedPolygon> sides;
  const int n = static_cast<int>(d.corners.size());
  for (int i = 0; i < n; ++i) {
    const Vec2 a = d.corners[i], b = d.corners[(i + 1) % n];
    // Walls face the inside: counter-clockwise corners and z up, so (a, b, b+z, a+z) has its normal inwards.
    sides.push_back({"side-" + std::to_string(i + 1),
                     {{a.x(), a.y(), 0}, {a.x(), a.y(), 10}, {b.x(), b.y(), 10}, {b.x(), b.y(), 0}},
                     d.rho[i],
                     d.E[i]});
  }
  e.sceneJson = sceneJsonText("Duct", sides);
  e.sceneObj = sceneObjText(sides);
}

Eigen::MatrixXd ductK(const Duct& d) {
  return Eigen::MatrixXd::Identity(d.F.rows(), d.F.cols()) - d.rho.asDiagonal() * d.F;
}

}  // namespace rt::homework
