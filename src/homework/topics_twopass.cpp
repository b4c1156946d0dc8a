// The two-pass method at one point (Wallace, Cohen and Greenberg 1987): the first pass is a radiosity
// solution of the room; the second computes a visible point's light as the direct part, from the lamp
// treated as a small source, plus the indirect part gathered from the first pass's radiosities of every other
// surface, B_j times the point-to-surface form factor. The lamp must not be gathered again: its light is the
// direct part. The form factors are the core's (Lambert's formula for a point and a polygon), printed to four
// significant digits, and the key is computed from the printed numbers; the tests compare them with the
// core's Nusselt projection and the direct part with the lamp's exact form factor.
#include <cmath>
#include <numbers>

#include "core/formfactor/analytic.h"
#include "homework/topics.h"

namespace rt::homework {

std::optional<Exercise> generateTwoPass(Draw& draw) {
  constexpr double kPi = std::numbers::pi;
  const double W = draw.value(3, 6, 0.5), D = draw.value(3, 6, 0.5), H = draw.value(2.5, 3.5, 0.1);
  const double px = draw.value(0.5, W - 0.5, 0.1), py = draw.value(0.5, D - 0.5, 0.1);
  const double lx = draw.value(1, W - 1, 0.1), ly = draw.value(1, D - 1, 0.1), s = draw.value(0.2, 0.4, 0.05);
  const double BL = draw.value(1000, 8000, 100), rho = draw.value(0.3, 0.8, 0.05);
  const Vec3 P(px, py, 0), n(0, 0, 1);
  const double dx = lx - px, dy = ly - py, r2 = dx * dx + dy * dy + H * H, r = std::sqrt(r2);
  if (s > r / 8) return std::nullopt;  // the lamp must be small seen from the point
  const std::vector<std::pair<std::string, Polygon>> surfaces{
      {"lamp",
       {Vec3(lx - s / 2, ly - s / 2, H), Vec3(lx - s / 2, ly + s / 2, H), Vec3(lx + s / 2, ly + s / 2, H),
        Vec3(lx + s / 2, ly - s / 2, H)}},
      {"ceiling", {Vec3(0, 0, H), Vec3(0, D, H), Vec3(W, D, H), Vec3(W, 0, H)}},
      {"wall $x = 0$", {Vec3(0, 0, 0), Vec3(0, D, 0), Vec3(0, D, H), Vec3(0, 0, H)}},
      {"wall $x = " + num(W) + "$", {Vec3(W, 0, 0), Vec3(W, 0, H), Vec3(W, D, H), Vec3(W, D, 0)}},
      {"wall $y = 0$", {Vec3(0, 0, 0), Vec3(0, 0, H), Vec3(W, 0, H), Vec3(W, 0, 0)}},
      {"wall $y = " + num(D) + "$", {Vec3(0, D, 0), Vec3(W, D, 0), Vec3(W, D, H), Vec3(0, D, H)}},
  };
  const int count = static_cast<int>(surfaces.size());
  Eigen::MatrixXd table(count, 2);  // B_j, F_Pj
  for (int j = 0; j < count; ++j) {
    double F = pointToPolygonFormFactor(P, n, surfaces[j].second);
    if (j == 1) F -= pointToPolygonFormFactor(P, n, surfaces[0].second);  // the ceiling around the lamp
    if (!(F > 0)) return std::nullopt;
    const double scale = std::pow(10.0, 3 - std::floor(std::log10(F)));  // four significant digits
    table(j, 1) = std::round(scale * F) / scale;
    table(j, 0) = j == 0 ? BL : draw.value(j == 1 ? 5 : 10, j == 1 ? 40 : 80, 1);
  }
  const double Hd = BL * s * s / kPi * (H / r) * (H / r) / r2;
  double Hi = 0;
  for (int j = 1; j < count; ++j) Hi += table(j, 0) * table(j, 1);
  const double lampGathered = table(0, 0) * table(0, 1);
  const double B = rho * (Hd + Hi), L = B / kPi;

  Exercise e;
  e.title = "The two-pass method at a point";
  e.given = {{"W", W},   {"D", D},   {"H", H},    {"px", px},   {"py", py},
             {"lx", lx}, {"ly", ly}, {"side", s}, {"lamp", BL}, {"rho", rho}};
  std::string rows = "| surface | $B_j$ (W/m²) | $F_{x j}$ |\n|---|---|---|\n";
  for (int j = 0; j < count; ++j)
    rows += "| " + surfaces[j].first + " | " + num(table(j, 0)) + " | " + num(table(j, 1), 4) + " |\n";
  e.statement =
      "A room spans $0 \\le x \\le " + num(W) + "$, $0 \\le y \\le " + num(D) + "$, $0 \\le z \\le " +
      num(H) + "$ m. A square lamp of side $" + num(s) + "$ m, centred at $(" + num(lx) + ", " + num(ly) +
      ", " + num(H) + ")$ on the ceiling, faces down with the radiosity $B_L = " + num(BL) +
      "$ W/m². The first pass solved the room; the table gives its radiosities and the form factors from the "
      "floor point $x = (" +
      num(px) + ", " + num(py) + ", 0)$ to each surface. The floor there reflects $\\rho = " + num(rho) +
      "$. In the second pass, find the direct irradiance at $x$ with the lamp treated as a small source, the "
      "indirect irradiance gathered from the first pass, the radiosity at $x$ and the radiance it sends to "
      "the eye.\n\n" +
      rows;
  e.hint =
      "A small Lambertian source gives $H_d = B_L A_L \\cos\\theta_L \\cos\\theta_x / (\\pi r^2)$. The "
      "gather sums $F_{xj} B_j$ over every surface but the lamp: the lamp's light is the direct part "
      "already.";
  e.solution = {
      "$r^2 = " + num(dx * dx + dy * dy, 6) + " + " + num(H * H, 6) + " = " + num(r2, 6) +
          "$ m², $\\cos\\theta_L = \\cos\\theta_x = h / r = " + num(H / r, 6) + "$.",
      "Direct: $H_d = B_L A_L \\cos\\theta_L \\cos\\theta_x / (\\pi r^2) = " + num(BL) + " \\times " +
          num(s * s, 6) + " \\times " + num(H * H / r2, 6) + " / (\\pi \\times " + num(r2, 6) +
          ") = " + num(Hd, 6) + "$ W/m².",
      "Indirect: $H_i = \\sum_{j \\ne L} F_{xj} B_j = " + num(Hi, 6) + "$ W/m² (the lamp's row, " +
          num(lampGathered, 6) + ", is left out: it is the direct part).",
      "Radiosity: $B_x = \\rho (H_d + H_i) = " + num(rho) + " \\times " + num(Hd + Hi, 6) + " = " +
          num(B, 6) + "$ W/m²; radiance to the eye $L_x = B_x / \\pi = " + num(L, 6) + "$ W/(m²·sr).",
  };
  e.questions = {
      {"Hd",
       "direct irradiance $H_d$ in W/m²",
       Hd,
       tolerance(Hd, 0.002, 1e-6),
       false,
       {{"one cosine left out", BL * s * s / kPi * (H / r) / r2},
        {"pi left out", BL * s * s * (H / r) * (H / r) / r2},
        {"the lamp's form factor from the table used (F_xL B_L)", lampGathered}}},
      {"Hi",
       "indirect irradiance $H_i$ in W/m²",
       Hi,
       tolerance(Hi, 0.002, 1e-6),
       false,
       {{"the lamp gathered again (its light counted twice)", Hi + lampGathered}}},
      {"B",
       "radiosity $B_x$ in W/m²",
       B,
       tolerance(B, 0.002, 1e-6),
       false,
       {{"the lamp counted twice", rho * (Hd + Hi + lampGathered)},
        {"rho left out", Hd + Hi},
        {"the direct part only", rho * Hd}}},
      {"L",
       "radiance $L_x$ in W/(m²·sr)",
       L,
       tolerance(L, 0.002, 1e-6),
       false,
       {{"the radiosity given for the radiance (no division by pi)", B}}},
  };
  e.data = {{"surfaces", table}};
  return e;
}

}  // namespace rt::homework
