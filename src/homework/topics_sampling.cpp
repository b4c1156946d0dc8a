// Form factors from samples: the hemicube's delta form factors at pixel centres and the F of a footprint, and
// a ray-cast (area-to-area) estimate from a printed table of random numbers with its standard error.
#include <cmath>
#include <numbers>

#include "homework/catalogue.h"
#include "homework/scene_text.h"
#include "homework/topics.h"

namespace rt::homework {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

std::optional<Exercise> generateHemicube(Draw& draw) {
  const int res = 2 * draw.integer(4, 8);  // 8 .. 16 pixels across the top face
  const double p = 2.0 / res;              // pixel side on the top face (and the sides)
  auto centre = [&](int k) { return -1 + (k + 0.5) * p; };
  // A top pixel and a side pixel (on the face x = 1: across y, up z).
  const int tx = draw.integer(0, res - 1), ty = draw.integer(0, res - 1);
  const int sy = draw.integer(0, res - 1), sz = draw.integer(0, res / 2 - 1);
  const double x = centre(tx), y = centre(ty), ys = centre(sy), zs = (sz + 0.5) * p;
  const double dA = p * p;
  const double dTop = dA / (kPi * std::pow(x * x + y * y + 1, 2));
  const double dSide = zs * dA / (kPi * std::pow(ys * ys + zs * zs + 1, 2));
  // Exact per-pixel values (Lambert) bound the centre rule's own error: the tolerance allows for it.
  const Vec3 o(0, 0, 0), n(0, 0, 1);
  auto topSquare = [&](double cx, double cy) {
    return Polygon{{cx - p / 2, cy - p / 2, 1},
                   {cx - p / 2, cy + p / 2, 1},
                   {cx + p / 2, cy + p / 2, 1},
                   {cx + p / 2, cy - p / 2, 1}};
  };
  const double exactTop = lambert(o, n, topSquare(x, y));
  const double exactSide = lambert(o, n,
                                   {{1, ys - p / 2, zs - p / 2},
                                    {1, ys + p / 2, zs - p / 2},
                                    {1, ys + p / 2, zs + p / 2},
                                    {1, ys - p / 2, zs + p / 2}});
  // The patch: a rectangle parallel to the element at height H whose projection stays inside the top face.
  const double H = draw.value(1, 3, 0.1);
  const double x0 = draw.value(-0.9 * H, 0.6 * H, 0.05), y0 = draw.value(-0.9 * H, 0.6 * H, 0.05);
  const double x1 = x0 + draw.value(0.2 * H, 0.9 * H, 0.05), y1 = y0 + draw.value(0.2 * H, 0.9 * H, 0.05);
  if (x1 > 0.95 * H || y1 > 0.95 * H) return std::nullopt;  // out of the top face's field of view
  int pixels = 0;
  double F = 0, exactF = 0, centreError = 0;
  std::string list;
  for (int a = 0; a < res; ++a)
    for (int b = 0; b < res; ++b) {
      const double cx = centre(a), cy = centre(b);
      const double ex = cx * H, ey = cy * H;  // where the pixel's centre ray meets the patch's plane
      const double margin = 1e-6 * H;
      if (std::abs(ex - x0) < margin || std::abs(ex - x1) < margin || std::abs(ey - y0) < margin ||
          std::abs(ey - y1) < margin)
        return std::nullopt;  // a centre on the outline: coverage ambiguous
      if (ex < x0 || ex > x1 || ey < y0 || ey > y1) continue;
      const double d = dA / (kPi * std::pow(cx * cx + cy * cy + 1, 2));
      const double exact = lambert(o, n, topSquare(cx, cy));
      F += d;
      exactF += exact;
      centreError += std::abs(d - exact);
      ++pixels;
      if (pixels <= 6) list += (pixels > 1 ? ", " : "") + std::string("$(") + num(cx) + ", " + num(cy) + ")$";
    }
  if (pixels < 4) return std::nullopt;  // an empty or one-pixel footprint says nothing
  Exercise e;
  e.title = "Hemicube delta form factors";
  e.given = {{"resolution", res}, {"x", x}, {"y", y}, {"side_y", ys}, {"side_z", zs}, {"height", H}};
  e.statement =
      "A hemicube of resolution $" + std::to_string(res) + " \\times " + std::to_string(res) +
      "$ sits on an element at the origin facing $+z$ (top face $z = 1$, $-1 \\le x, y \\le 1$; side faces "
      "of height 1, with pixels of the same size $" +
      num(p) + " \\times " + num(p) + "$). (a) The delta form factor of the top pixel whose centre is $(" +
      num(x) + ", " + num(y) +
      ", 1)$. (b) The delta form factor of the pixel on the side face $x = 1$ whose centre is $(1, " +
      num(ys) + ", " + num(zs) + ")$. A rectangle parallel to the element, at height $" + num(H) +
      "$, spans $" + num(x0) + " \\le x \\le " + num(x1) + "$, $" + num(y0) + " \\le y \\le " + num(y1) +
      "$ and faces down. (c) How many top pixels have their centre inside its projection, and (d) the "
      "form factor they sum to.";
  e.hint =
      "Top face: $\\Delta F = \\frac{\\Delta A}{\\pi (x^2 + y^2 + 1)^2}$; side face $x = 1$: $\\Delta F = "
      "\\frac{z\\,\\Delta A}{\\pi (y^2 + z^2 + 1)^2}$. A pixel centre $(x, y, 1)$ sees the point $(Hx, Hy, "
      "H)$ "
      "of the rectangle's plane.";
  e.solution.push_back("$\\Delta A = " + num(dA, 6) + "$. (a) $\\Delta F = \\frac{" + num(dA, 6) + "}{\\pi(" +
                       num(x * x + y * y + 1, 6) + ")^2} = " + num(dTop, 6) + "$ (exact over the pixel: $" +
                       num(exactTop, 6) + "$).");
  e.solution.push_back("(b) $\\Delta F = \\frac{" + num(zs) + " \\times " + num(dA, 6) + "}{\\pi(" +
                       num(ys * ys + zs * zs + 1, 6) + ")^2} = " + num(dSide, 6) + "$ (exact: $" +
                       num(exactSide, 6) + "$).");
  e.solution.push_back("(c) The projection onto $z = 1$ is $" + num(x0 / H, 5) + " \\le x \\le " +
                       num(x1 / H, 5) + "$, $" + num(y0 / H, 5) + " \\le y \\le " + num(y1 / H, 5) + "$; " +
                       std::to_string(pixels) + " pixel centres fall inside (first: " + list + ").");
  e.solution.push_back("(d) Their delta form factors sum to $F = " + num(F, 6) +
                       "$ (the exact pixel integrals sum to $" + num(exactF, 6) + "$).");
  e.questions = {
      {"dTop",
       "(a) $\\Delta F$ of the top pixel",
       dTop,
       std::max(tolerance(dTop, 0.005, 1e-7), 1.5 * std::abs(dTop - exactTop)),
       false,
       {{"1/pi left out", dTop * kPi},
        {"power 1 instead of 2 in the denominator", dA / (kPi * (x * x + y * y + 1))}}},
      {"dSide",
       "(b) $\\Delta F$ of the side pixel",
       dSide,
       std::max(tolerance(dSide, 0.005, 1e-7), 1.5 * std::abs(dSide - exactSide)),
       false,
       {{"top-face formula used for a side pixel (no factor z)",
         dA / (kPi * std::pow(ys * ys + zs * zs + 1, 2))}}},
      {"pixels", "(c) pixels in the footprint", static_cast<double>(pixels), 0.5, true, {}},
      {"F", "(d) $F$ of the footprint", F, std::max(tolerance(F, 0.005, 1e-6), 1.5 * centreError), false, {}},
  };
  Figure f;
  for (int k = 0; k <= res; ++k) {
    f.line({-1 + k * p, -1}, {-1 + k * p, 1});
    f.line({-1, -1 + k * p}, {1, -1 + k * p});
  }
  f.polygon({{x0 / H, y0 / H}, {x1 / H, y0 / H}, {x1 / H, y1 / H}, {x0 / H, y1 / H}}, "accent");
  f.label({0, -1.15}, "top face, x to the right, y up");
  f.caption = "The top face's pixels and the rectangle's projection.";
  e.figure = f;
  const double s = 0.02;
  const std::vector<NamedPolygon> surfaces{
      {"element", {{-s, -s, 0}, {s, -s, 0}, {s, s, 0}, {-s, s, 0}}},
      {"rectangle", {{x0, y0, H}, {x0, y1, H}, {x1, y1, H}, {x1, y0, H}}}};
  e.sceneJson = sceneJsonText("Hemicube footprint", surfaces);
  e.sceneObj = sceneObjText(surfaces);
  return e;
}

namespace {

// Two parallel patches facing each other: i at z = 0 from the origin, j at z = h, shifted along x.
struct FacingPatches {
  double a, b, c, w, h, shift;
  std::vector<NamedPolygon> surfaces() const {
    return {{"patch-i", {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}}},
            {"patch-j", {{shift, 0, h}, {shift, c, h}, {shift + w, c, h}, {shift + w, 0, h}}}};
  }
  std::string describe() const {
    return "Patch $i$ is the rectangle $0 \\le x \\le " + num(a) + "$, $0 \\le y \\le " + num(b) +
           "$ at $z = 0$ facing up; patch $j$ is $" + num(shift) + " \\le x \\le " + num(shift + w) +
           "$, $0 \\le y \\le " + num(c) + "$ at $z = " + num(h) + "$ facing down.";
  }
};

FacingPatches drawFacingPatches(Draw& draw) {
  FacingPatches p;
  p.a = draw.value(0.5, 1.5, 0.1);
  p.b = draw.value(0.5, 1.5, 0.1);
  p.c = draw.value(0.6, 1.5, 0.1);
  p.w = draw.value(0.4, 1.5, 0.1);
  p.h = draw.value(0.8, 2, 0.1);
  p.shift = draw.value(-0.5, 0.5, 0.1);
  return p;
}

// The local-line estimate: N lines leave i from uniform points in cosine-distributed directions; the share
// that reaches j first estimates F_ij (a binomial proportion, with its standard error).
std::optional<Exercise> generateLocalLines(Draw& draw) {
  const FacingPatches g = drawFacingPatches(draw);
  const int N = draw.integer(12, 20);
  Eigen::MatrixXd table(N, 4);
  std::vector<std::string> steps;
  int hits = 0, first = 0;
  for (int k = 0; k < N; ++k) {
    for (int m = 0; m < 4; ++m) table(k, m) = std::round(1000 * draw.uniform()) / 1000;
    const Vec3 x(g.a * table(k, 0), g.b * table(k, 1), 0);
    const double r = std::sqrt(table(k, 2)), phi = 2 * kPi * table(k, 3);
    const Vec3 d(r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - table(k, 2)));
    if (d.z() < 1e-3) return std::nullopt;  // a line along the plane never reaches j
    const Vec3 p = x + (g.h / d.z()) * d;
    const double margin = std::min(
        {std::abs(p.x() - g.shift), std::abs(p.x() - g.shift - g.w), std::abs(p.y()), std::abs(p.y() - g.c)});
    if (margin < 2e-3)
      return std::nullopt;  // a line grazing j's outline: hit or miss is a matter of rounding
    const bool hit = p.x() > g.shift && p.x() < g.shift + g.w && p.y() > 0 && p.y() < g.c;
    hits += hit;
    if (k == 0) first = hit;
    steps.push_back("Line " + std::to_string(k + 1) + ": $x = " + vectorLatex(x, 5) +
                    "$, $d = " + vectorLatex(d, 5) + "$, meets $z = " + num(g.h) + "$ at $" +
                    vectorLatex(p, 5) + "$: " + (hit ? "hits $j$." : "misses."));
  }
  if (hits == 0 || hits == N) return std::nullopt;  // a standard error of 0 says nothing
  const double p = static_cast<double>(hits) / N;
  const double sd = std::sqrt(p * (1 - p) * N / (N - 1)), se = sd / std::sqrt(N);
  Exercise e;
  e.title = "A local-line estimate and its standard error";
  e.given = {{"a", g.a}, {"b", g.b},         {"c", g.c}, {"w", g.w},
             {"h", g.h}, {"shift", g.shift}, {"N", N},   {"lines", 1}};
  e.statement =
      g.describe() + " Estimate $F_{ij}$ with the " + std::to_string(N) +
      " local lines of the table `samples` (columns $u_1, v_1, u_2, v_2$): line $k$ leaves $x_k = (" +
      num(g.a) + "u_1, " + num(g.b) +
      "v_1, 0)$ in the cosine-distributed direction $d_k = (\\sqrt{u_2}"
      "\\cos 2\\pi v_2, \\sqrt{u_2}\\sin 2\\pi v_2, \\sqrt{1 - u_2})$ and counts when it reaches $j$. "
      "Give whether line 1 hits (1/0), the number of hits, $\\hat F = \\text{hits}/N$ and its standard "
      "error $s/\\sqrt N$ ($s$ the sample standard deviation of the 0/1 scores, divisor $N - 1$).";
  e.hint = "Follow each line to the plane $z = " + num(g.h) +
           "$: $x_k + (h/d_z)\\,d_k$, then check the rectangle. "
           "For 0/1 scores, $s^2 = \\frac{N}{N-1}\\hat F(1 - \\hat F)$.";
  e.solution = steps;
  e.solution.push_back(std::to_string(hits) + " hits: $\\hat F = " + std::to_string(hits) + "/" +
                       std::to_string(N) + " = " + num(p, 6) + "$, $s = " + num(sd, 6) +
                       "$, standard error $" + num(se, 6) + "$.");
  e.questions = {
      {"hit1", "line 1 hits $j$ (1 = yes, 0 = no)", static_cast<double>(first), 0.5, true, {}},
      {"hits", "hits", static_cast<double>(hits), 0.5, true, {}},
      {"F", "$\\hat F$", p, tolerance(p, 0.002, 1e-5), false, {{"misses counted instead of hits", 1 - p}}},
      {"SE",
       "standard error",
       se,
       tolerance(se, 0.005, 1e-5),
       false,
       {{"standard deviation given for the standard error (not divided by sqrt N)", sd},
        {"divisor N instead of N - 1", std::sqrt(p * (1 - p) / N)}}},
  };
  e.data.push_back({"samples", table});
  e.statement += "\n\n" + markdownTable(table, {"$u_1$", "$v_1$", "$u_2$", "$v_2$"}) + "\n";
  e.sceneJson = sceneJsonText("Local lines", g.surfaces());
  e.sceneObj = sceneObjText(g.surfaces());
  return e;
}

}  // namespace

std::optional<Exercise> generateRaycast(Draw& draw) {
  // Half the variants estimate with local lines, half by sampling point pairs and the kernel.
  if (draw.uniform() < 0.5) return generateLocalLines(draw);
  const double a = draw.value(0.5, 1.5, 0.1), b = draw.value(0.5, 1.5, 0.1);  // patch i at z = 0
  const double c = draw.value(0.6, 1.5, 0.1), w = draw.value(0.4, 1.5, 0.1);  // patch j at z = h, w x c
  const double h = draw.value(0.8, 2, 0.1), shift = draw.value(-0.5, 0.5, 0.1);
  const int N = draw.integer(8, 12);
  const double Ai = a * b, Aj = w * c;
  Eigen::MatrixXd table(N, 4);
  std::vector<double> f(N);
  std::vector<double> bare(N);
  for (int k = 0; k < N; ++k) {
    for (int m = 0; m < 4; ++m) table(k, m) = std::round(1000 * draw.uniform()) / 1000;
    const Vec3 x(a * table(k, 0), b * table(k, 1), 0), y(shift + w * table(k, 2), c * table(k, 3), h);
    const double r2 = (y - x).squaredNorm();
    f[k] = Aj * h * h / (kPi * r2 * r2);  // cos_i = cos_j = h / r
    bare[k] = Aj / (kPi * r2);
  }
  double mean = 0;
  for (double v : f) mean += v / N;
  double ss = 0;
  for (double v : f) ss += (v - mean) * (v - mean);
  const double sd = std::sqrt(ss / (N - 1)), se = sd / std::sqrt(N);
  if (!(se > 0)) return std::nullopt;
  Exercise e;
  e.title = "A ray-cast estimate and its standard error";
  e.given = {{"a", a}, {"b", b}, {"c", c}, {"w", w}, {"h", h}, {"shift", shift}, {"N", N}};
  e.statement =
      "Patch $i$ is the rectangle $0 \\le x \\le " + num(a) + "$, $0 \\le y \\le " + num(b) +
      "$ at $z = 0$ facing up; patch $j$ is $" + num(shift) + " \\le x \\le " + num(shift + w) +
      "$, $0 \\le y \\le " + num(c) + "$ at $z = " + num(h) + "$ facing down. Estimate $F_{ij}$ with the " +
      std::to_string(N) + " sample pairs of the table `samples` (columns $u_1, v_1, u_2, v_2$): $x_k = (" +
      num(a) + "u_1, " + num(b) + "v_1, 0)$, $y_k = (" + num(shift) + " + " + num(w) + "u_2, " + num(c) +
      "v_2, " + num(h) +
      ")$, $f_k = A_j\\frac{\\cos\\theta_i\\cos\\theta_j}{\\pi r_k^2}$, $\\hat F = \\frac1N\\sum_k f_k$. "
      "Give "
      "$f_1$, $\\hat F$ and its standard error $s/\\sqrt N$ ($s$ the sample standard deviation, divisor "
      "$N - 1$).";
  e.hint = "Both cosines are $h/r$ here, so $f_k = A_j h^2 / (\\pi r^4)$.";
  for (int k = 0; k < N; ++k) {
    const Vec3 x(a * table(k, 0), b * table(k, 1), 0), y(shift + w * table(k, 2), c * table(k, 3), h);
    e.solution.push_back("Sample " + std::to_string(k + 1) + ": $x = " + vectorLatex(x, 5) +
                         "$, $y = " + vectorLatex(y, 5) + "$, $r^2 = " + num((y - x).squaredNorm(), 6) +
                         "$, $f = " + num(f[k], 6) + "$.");
  }
  e.solution.push_back("$\\hat F = " + num(mean, 6) + "$, $s = " + num(sd, 6) + "$, standard error $" +
                       num(se, 6) + "$.");
  e.questions = {
      {"f1",
       "$f_1$",
       f[0],
       tolerance(f[0], 0.002, 1e-5),
       false,
       {{"cosines left out", bare[0]}, {"A_i used for A_j", f[0] * Ai / Aj}}},
      {"F", "$\\hat F$", mean, tolerance(mean, 0.002, 1e-5), false, {{"A_i used for A_j", mean * Ai / Aj}}},
      {"SE",
       "standard error",
       se,
       tolerance(se, 0.005, 1e-5),
       false,
       {{"standard deviation given for the standard error (not divided by sqrt N)", sd},
        {"divisor N instead of N - 1", std::sqrt(ss / N) / std::sqrt(N)}}},
  };
  e.data.push_back({"samples", table});
  e.statement += "\n\n" + markdownTable(table, {"$u_1$", "$v_1$", "$u_2$", "$v_2$"}) + "\n";
  const std::vector<NamedPolygon> surfaces{
      {"patch-i", {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}}},
      {"patch-j", {{shift, 0, h}, {shift, c, h}, {shift + w, c, h}, {shift + w, 0, h}}}};
  e.sceneJson = sceneJsonText("Ray-cast estimate", surfaces);
  e.sceneObj = sceneObjText(surfaces);
  return e;
}

}  // namespace rt::homework
