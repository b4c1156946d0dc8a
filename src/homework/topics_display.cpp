// From radiosity to pixels and back to the mesh: exposure, tone map and sRGB gamma to 8-bit values, and the
// gradient criterion of adaptive subdivision (core/refine). Written from the formulas in the lessons; the
// tests compare with the viewer's display pipeline and the core's luminance.
#include <algorithm>
#include <cmath>

#include "homework/topics.h"

namespace rt::homework {
namespace {

double srgb(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

double eightBit(double unit) {
  return std::round(std::clamp(unit, 0.0, 1.0) * 255.0);
}

double luminanceOf(const Vec3& rgb) {
  return 0.2126 * rgb.x() + 0.7152 * rgb.y() + 0.0722 * rgb.z();
}

}  // namespace

std::optional<Exercise> generateToneMapping(Draw& draw) {
  const bool reinhard = draw.uniform() < 0.5;
  const double exposure = draw.value(0.2, 2, 0.05);
  const int count = 4;
  Eigen::VectorXd B(count);
  for (int i = 0; i < count; ++i) B[i] = draw.value(0.02, reinhard ? 6 : 1.2 / exposure, 0.01);
  Exercise e;
  e.title = "Tone mapping to 8-bit";
  e.given = {{"exposure", exposure}, {"reinhard", reinhard ? 1.0 : 0.0}};
  e.data.push_back({"B", B});
  const std::string map = reinhard ? "Reinhard's $y = x/(1+x)$" : "the linear clamp $y = \\min(x, 1)$";
  e.statement = "Four elements have radiosities $B = " + vectorLatex(B) +
                "$ (one channel). Display them with "
                "exposure $" +
                num(exposure) + "$ ($x = " + num(exposure) + "B$), tone map " + map +
                ", the sRGB curve ($12.92y$ for $y \\le 0.0031308$, else $1.055y^{1/2.4} - 0.055$) and 8-bit "
                "quantisation $\\operatorname{round}(255\\,v)$.";
  e.hint =
      "Exposure first, then the tone map, then gamma exactly once, then round; the sRGB curve is not a plain "
      "power $1/2.2$.";
  for (int i = 0; i < count; ++i) {
    const double x = exposure * B[i], y = reinhard ? x / (1 + x) : std::min(x, 1.0), v = srgb(y);
    const double scaled = 255 * v;
    // Well-posed: not within 0.05 of a rounding boundary.
    if (std::abs(scaled - std::floor(scaled) - 0.5) < 0.05) return std::nullopt;
    const std::string k = std::to_string(i + 1);
    e.solution.push_back("Element " + k + ": $x = " + num(x, 6) + "$, tone mapped $y = " + num(y, 6) +
                         "$, sRGB $v = " + num(v, 6) + "$, $255v = " + num(scaled, 6) + "$, 8-bit value $" +
                         num(eightBit(v)) + "$.");
    e.questions.push_back(
        {"v" + k,
         "8-bit value of element " + k,
         eightBit(v),
         0.5,
         true,
         {{"gamma applied twice", eightBit(srgb(v))},
          {"gamma not applied", eightBit(y)},
          {"power law 1/2.2 used for the sRGB curve", eightBit(std::pow(y, 1 / 2.2))},
          {"exposure left out", eightBit(srgb(reinhard ? B[i] / (1 + B[i]) : std::min(B[i], 1.0)))}}});
  }
  return e;
}

std::optional<Exercise> generateSubdivision(Draw& draw) {
  const int n = 6;  // the element under test (1), its neighbours (2-4), an emitter (5), one more element (6)
  std::vector<Vec3> B(n);
  Eigen::VectorXd area(n);
  for (int i = 0; i < n; ++i) {
    const double grey = draw.value(0.5, 4, 0.05);
    B[i] = Vec3(grey * draw.value(0.7, 1.2, 0.05), grey * draw.value(0.7, 1.2, 0.05),
                grey * draw.value(0.7, 1.2, 0.05));
    area[i] = draw.value(0.1, 1, 0.05);
  }
  B[4] *= 8;  // the light
  const double tol = draw.value(0.15, 0.6, 0.05), minEdge = draw.value(0.05, 0.2, 0.01);
  const double edge = draw.uniform() < 0.2 ? draw.value(minEdge, 2 * minEdge * 0.95, 0.01)
                                           : draw.value(2.1 * minEdge, 1, 0.01);
  Eigen::VectorXd Y(n);
  for (int i = 0; i < n; ++i) Y[i] = luminanceOf(B[i]);
  double wsum = 0, asum = 0, wall = 0, plain = 0;
  for (int i = 0; i < n; ++i) {
    wall += area[i] * Y[i];
    if (i == 4) continue;
    wsum += area[i] * Y[i];
    asum += area[i];
    plain += Y[i] / (n - 1);
  }
  const double mean = wsum / asum, threshold = tol * mean;
  double jump = 0;
  for (int j = 1; j <= 3; ++j) jump = std::max(jump, std::abs(Y[0] - Y[j]));
  if (std::abs(jump - threshold) < 0.05 * threshold) return std::nullopt;  // a clear decision either way
  const bool split = jump > threshold && edge >= 2 * minEdge;
  Exercise e;
  e.title = "The adaptive subdivision criterion";
  e.given = {{"tolerance", tol}, {"min_edge", minEdge}, {"edge", edge}};
  Eigen::MatrixXd elements(n, 4);
  for (int i = 0; i < n; ++i) elements.row(i) << area[i], B[i].x(), B[i].y(), B[i].z();
  e.data.push_back({"elements", elements});
  std::string table = "| element | area | $B$ (r, g, b) |\n|---|---|---|\n";
  for (int i = 0; i < n; ++i)
    table += "| " + std::to_string(i + 1) + (i == 4 ? " (emitter)" : "") + " | " + num(area[i]) + " | " +
             num(B[i].x()) + ", " + num(B[i].y()) + ", " + num(B[i].z()) + " |\n";
  e.statement =
      "After a solve, the mesh's elements have these radiosities:\n\n" + table +
      "\nElement 1's neighbours on the same surface are 2, 3 and 4; its longest edge is $" + num(edge) +
      "$ m. The criterion splits an element when its luminance $Y = 0.2126R + 0.7152G + 0.0722B$ differs "
      "from a neighbour's by more than $t = " +
      num(tol) +
      "$ times the area-weighted mean luminance of "
      "the reflecting (non-emitting) elements, unless halving it would make an edge shorter than the "
      "minimum $" +
      num(minEdge) +
      "$ m. Give $Y_1$, the mean, the threshold, the largest jump and whether "
      "element 1 is split (1 = yes, 0 = no).";
  e.hint =
      "Leave the emitter out of the mean and weight by area; the element splits only if the jump is over "
      "the threshold and its longest edge is at least twice the minimum.";
  e.solution.push_back("Luminances: $Y = " + vectorLatex(Y, 6) + "$.");
  e.solution.push_back("Area-weighted mean over elements 1-4 and 6: $" + num(wsum, 6) + " / " + num(asum, 6) +
                       " = " + num(mean, 6) + "$; threshold $" + num(tol) + " \\times " + num(mean, 6) +
                       " = " + num(threshold, 6) + "$.");
  e.solution.push_back("Jumps to 2, 3, 4: $" + num(std::abs(Y[0] - Y[1]), 6) + "$, $" +
                       num(std::abs(Y[0] - Y[2]), 6) + "$, $" + num(std::abs(Y[0] - Y[3]), 6) +
                       "$; largest $" + num(jump, 6) + "$.");
  e.solution.push_back(std::string(jump > threshold ? "Over" : "Under") +
                       " the threshold; the longest edge $" + num(edge) + "$ is " +
                       (edge >= 2 * minEdge ? "at least" : "less than") + " $2 \\times " + num(minEdge) +
                       "$: " + (split ? "split (1)." : "not split (0)."));
  e.questions = {
      {"Y1",
       "$Y_1$",
       Y[0],
       tolerance(Y[0], 0.002, 1e-4),
       false,
       {{"mean of R, G, B used for luminance", B[0].mean()}}},
      {"mean",
       "area-weighted mean luminance",
       mean,
       tolerance(mean, 0.002, 1e-4),
       false,
       {{"emitter included in the mean", wall / area.sum()}, {"mean not weighted by area", plain}}},
      {"threshold",
       "threshold",
       threshold,
       tolerance(threshold, 0.002, 1e-4),
       false,
       {{"emitter included in the mean", tol * wall / area.sum()}}},
      {"jump", "largest jump", jump, tolerance(jump, 0.002, 1e-4), false, {}},
      {"split",
       "split (1) or not (0)",
       split ? 1.0 : 0.0,
       0.5,
       true,
       {{"minimum edge not checked", jump > threshold ? 1.0 : 0.0}}},
  };
  return e;
}

}  // namespace rt::homework
