// Reflection by hand: a distant lamp lights a surface with a normalised Phong BRDF, and a viewer in the plane
// of incidence looks at it. The student finds the angle between the mirror direction and the viewer, the
// specular and whole BRDF there, and the radiance the viewer sees, L_o = f_r H (the lamp is small, so the
// integral of f_r L_i cos(theta_i) d(omega_i) over it is f_r times its irradiance). The key is computed here
// from the formula; the tests compare it with the core's BRDF (core/brdf.h), which shares no code with it.
#include <cmath>
#include <numbers>

#include "homework/topics.h"

namespace rt::homework {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

std::optional<Exercise> generatePhong(Draw& draw) {
  const double H = draw.value(50, 500, 10);  // W/m^2
  const double incidence = draw.value(10, 70, 5), offset = draw.value(-20, 20, 5);
  const double view = incidence + offset;
  const double kd = draw.value(0.2, 0.6, 0.05), ks = draw.value(0.1, 0.4, 0.05);
  const double q = draw.integer(2, 64);
  // A viewer off the mirror direction, above the surface, and an energy-conserving material.
  if (offset == 0 || view < 0 || view > 85 || kd + ks > 0.95) return std::nullopt;
  const double alpha = std::abs(view - incidence), cosAlpha = std::cos(alpha * kPi / 180);
  const double power = std::pow(cosAlpha, q), normalisation = (q + 2) / (2 * kPi);
  const double fs = ks * normalisation * power, f = kd / kPi + fs, L = f * H;

  Exercise e;
  e.title = "A Phong reflection";
  e.given = {{"H", H}, {"incidence", incidence}, {"view", view}, {"kd", kd}, {"ks", ks}, {"q", q}};
  e.statement =
      "A distant lamp gives a surface the irradiance $H = " + num(H) +
      "$ W/m², its light arriving at $\\theta_i = " + num(incidence) +
      "^\\circ$ from the normal. The surface reflects by the normalised Phong BRDF $f_r = k_d/\\pi + k_s "
      "\\frac{q+2}{2\\pi}\\cos^q\\alpha$ with $k_d = " +
      num(kd) + "$, $k_s = " + num(ks) + "$ and $q = " + num(q) +
      "$, where $\\alpha$ is the angle between the mirror direction of the light and the direction to the "
      "viewer. The viewer is in the plane of incidence, on the far side of the normal from the lamp, at "
      "$\\theta_o = " +
      num(view) +
      "^\\circ$ from the normal. Find $\\alpha$, the specular part of $f_r$, the whole $f_r$ and the "
      "radiance $L_o$ the viewer sees.";
  e.hint =
      "The mirror direction leaves at $\\theta_i$ on the far side of the normal, in the same plane as the "
      "viewer. The lamp is small: the reflection equation's integral over it is $f_r$ times the irradiance "
      "it gives, which already holds the $\\cos\\theta_i$.";
  e.solution = {
      "The mirror direction and the viewer lie in the plane of incidence on the same side of the normal, at "
      "$" +
          num(incidence) + "^\\circ$ and $" + num(view) + "^\\circ$: $\\alpha = |" + num(view) + " - " +
          num(incidence) + "|^\\circ = " + num(alpha) + "^\\circ$, $\\cos\\alpha = " + num(cosAlpha, 6) +
          "$.",
      "$\\cos^q\\alpha = " + num(cosAlpha, 6) + "^{" + num(q) + "} = " + num(power, 6) +
          "$; the normalisation is $(q+2)/(2\\pi) = " + num(normalisation, 6) +
          "$ per steradian, so the specular part is $k_s \\frac{q+2}{2\\pi}\\cos^q\\alpha = " + num(fs, 6) +
          "$ sr⁻¹.",
      "The diffuse part is $k_d/\\pi = " + num(kd / kPi, 6) + "$ sr⁻¹, and $f_r = " + num(kd / kPi, 6) +
          " + " + num(fs, 6) + " = " + num(f, 6) + "$ sr⁻¹.",
      "The radiance towards the viewer: $L_o = f_r H = " + num(f, 6) + " \\times " + num(H) + " = " +
          num(L, 6) + "$ W m⁻² sr⁻¹.",
  };
  const double wrongAlpha = incidence + view, cosWrong = std::cos(wrongAlpha * kPi / 180);
  e.questions = {
      {"alpha",
       "the angle $\\alpha$ in degrees",
       alpha,
       tolerance(alpha, 0.001, 0.05),
       false,
       {{"the angle between the lamp and the viewer (theta_i + theta_o), not between the mirror direction "
         "and "
         "the viewer",
         wrongAlpha}}},
      {"fs",
       "the specular part $k_s \\frac{q+2}{2\\pi}\\cos^q\\alpha$ in sr⁻¹",
       fs,
       tolerance(fs, 0.005, 1e-9),
       false,
       {{"the normalisation (q + 2) / (2 pi) left out", ks * power},
        {"(q + 1) / (2 pi), the lobe's own integral, used instead of (q + 2) / (2 pi)",
         ks * (q + 1) / (2 * kPi) * power},
        {"alpha measured from the lamp (theta_i + theta_o)",
         cosWrong > 0 ? ks * normalisation * std::pow(cosWrong, q) : 0.0}}},
      {"f",
       "the BRDF $f_r$ in sr⁻¹",
       f,
       tolerance(f, 0.005, 1e-9),
       false,
       {{"the diffuse part without its 1/pi (k_d + specular)", kd + fs},
        {"the specular part left out (Lambertian only)", kd / kPi},
        {"the normalisation left out", kd / kPi + ks * power}}},
      {"L",
       "the radiance $L_o$ in W m⁻² sr⁻¹",
       L,
       tolerance(L, 0.005, 1e-9),
       false,
       {{"the cosine of the incidence applied again (f_r H cos theta_i)",
         L * std::cos(incidence * kPi / 180)},
        {"divided by the cosine of the incidence", L / std::cos(incidence * kPi / 180)},
        {"the radiosity pi f_r H given instead of the radiance", kPi * L},
        {"the diffuse part's 1/pi left out", (kd + fs) * H}}},
  };
  return e;
}

}  // namespace rt::homework
