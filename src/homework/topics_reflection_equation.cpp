// One bounce of the reflection equation for a Lambertian surface: a round lamp of constant radiance L hangs
// above a point of a diffuse floor. The irradiance is the radiance integrated against the cosine over the
// lamp's solid angle, H = L pi sin^2(alpha) (a cap of half-angle alpha about the normal); a Lambertian
// surface reflects the radiance rho H / pi in every direction, and its radiosity is pi times that, rho H.
// Written from the definitions; the tests compare it with the core's point-to-polygon form factor of a
// many-sided disc (Lambert's formula), which shares no code with it.
#include <cmath>
#include <numbers>

#include "homework/topics.h"

namespace rt::homework {

std::optional<Exercise> generateReflectionEquation(Draw& draw) {
  constexpr double kPi = std::numbers::pi;
  const double L = draw.value(50, 500, 5);           // W/(m^2 sr)
  const double radius = draw.value(0.1, 0.6, 0.05);  // m
  const double height = draw.value(0.5, 3, 0.1);     // m
  const double rho = draw.value(0.2, 0.9, 0.05);
  const double s2 = radius * radius / (radius * radius + height * height);  // sin^2 of the cap's half-angle
  if (s2 < 0.01 || s2 > 0.9) return std::nullopt;
  const double cosAlpha = height / std::sqrt(radius * radius + height * height);
  const double H = kPi * L * s2, Lr = rho * H / kPi, B = kPi * Lr;

  Exercise e;
  e.title = "One bounce of the reflection equation";
  e.given = {{"radiance", L}, {"radius", radius}, {"height", height}, {"rho", rho}};
  e.statement =
      "A round lamp of radius $R = " + num(radius) + "$ m hangs face down at the height $h = " + num(height) +
      "$ m straight above a point $x$ of a diffuse floor; every point of the lamp sends the "
      "radiance $L = " +
      num(L) +
      "$ W/(m²·sr) in every direction. The floor is Lambertian with reflectance $\\rho = " + num(rho) +
      "$ and emits nothing. Seen from $x$ the lamp is a cap of half-angle $\\alpha$ about the "
      "normal. Find $\\sin^2\\alpha$ (the point-to-lamp form factor), the irradiance at $x$, the "
      "radiance the floor reflects and its radiosity.";
  e.hint =
      "Irradiance is $H = \\int L \\cos\\theta \\, d\\omega$ over the lamp; over a cap of half-angle "
      "$\\alpha$ the integral of $\\cos\\theta\\,d\\omega$ is $\\pi \\sin^2\\alpha$. A Lambertian BRDF is "
      "$\\rho/\\pi$.";
  e.solution = {
      "$\\sin^2\\alpha = R^2/(R^2 + h^2) = " + num(radius * radius, 6) + " / " +
          num(radius * radius + height * height, 6) + " = " + num(s2, 6) +
          "$: the fraction of the cosine-weighted hemisphere the lamp fills, its form factor from $x$.",
      "Irradiance: $H = \\int_\\text{lamp} L \\cos\\theta\\,d\\omega = L\\,\\pi\\sin^2\\alpha = " + num(L) +
          " \\times \\pi \\times " + num(s2, 6) + " = " + num(H, 6) + "$ W/m².",
      "Reflected radiance (one bounce of the reflection equation, BRDF $\\rho/\\pi$): $L_r = (\\rho/\\pi) H "
      "= " +
          num(rho) + " \\times " + num(H, 6) + " / \\pi = " + num(Lr, 6) +
          "$ W/(m²·sr), the same in every "
          "direction.",
      "Radiosity: $B = \\pi L_r = \\rho H = " + num(B, 6) + "$ W/m² (the floor emits nothing, so $E = 0$).",
  };
  const double omega = 2 * kPi * (1 - cosAlpha);  // the cap's solid angle, without the cosine
  e.questions = {
      {"s2",
       "$\\sin^2\\alpha$ (the form factor from $x$ to the lamp)",
       s2,
       tolerance(s2, 0.002, 1e-6),
       false,
       {{"the solid angle over 2 pi (1 - cos alpha): the cosine left out", 1 - cosAlpha},
        {"R / sqrt(R^2 + h^2): the sine, not its square", std::sqrt(s2)}}},
      {"H",
       "irradiance $H$ in W/m²",
       H,
       tolerance(H, 0.002, 1e-6),
       false,
       {{"L times the solid angle: the cosine left out", L * omega},
        {"pi left out (L sin^2 alpha)", L * s2},
        {"the whole hemisphere (pi L)", kPi * L}}},
      {"Lr",
       "reflected radiance $L_r$ in W/(m²·sr)",
       Lr,
       tolerance(Lr, 0.002, 1e-6),
       false,
       {{"the BRDF taken as rho, not rho / pi", rho * H},
        {"rho left out (H / pi)", H / kPi},
        {"the radiosity given for the radiance (no division by pi)", B}}},
      {"B",
       "radiosity $B$ in W/m²",
       B,
       tolerance(B, 0.002, 1e-6),
       false,
       {{"the radiance given for the radiosity (B = L_r)", Lr},
        {"rho left out (B = H)", H},
        {"the BRDF taken as rho, so pi times too much", kPi * rho * H}}},
  };
  return e;
}

}  // namespace rt::homework
