// Measuring light by hand: the solid angle a small tilted patch subtends at a point source, the source's
// intensity, the irradiance it gives the patch and the power the patch receives. The key is computed here
// from the definitions (d(omega) = cos(theta) dA / r^2, I = Phi / 4 pi, H = I cos(theta) / r^2); the tests
// compare it with the core's exact solid angle of the patch, which shares no code with it.
#include <cmath>
#include <numbers>

#include "homework/topics.h"

namespace rt::homework {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

std::optional<Exercise> generateIrradiance(Draw& draw) {
  const double power = draw.value(20, 200, 5);      // W
  const double r = draw.value(1, 5, 0.1);           // m
  const double side = draw.value(0.02, 0.1, 0.01);  // m
  const double tiltDegrees = draw.value(10, 75, 5);
  // Small enough that the small-patch approximation is within a quarter percent of the exact solid angle.
  if (r < 10 * side) return std::nullopt;
  const double area = side * side, cosine = std::cos(tiltDegrees * kPi / 180);
  const double omega = area * cosine / (r * r), intensity = power / (4 * kPi);
  const double H = intensity * cosine / (r * r), received = H * area;

  Exercise e;
  e.title = "Solid angle and irradiance";
  e.given = {{"power", power}, {"distance", r}, {"side", side}, {"tilt", tiltDegrees}};
  e.statement =
      "A small lamp radiates $\\Phi = " + num(power) +
      "$ W equally in all directions. A square patch of side $" + num(side) +
      "$ m has its centre $r = " + num(r) +
      "$ m from the lamp, and its normal makes the angle $\\theta = " + num(tiltDegrees) +
      "^\\circ$ with the line to the lamp. Treat the lamp as a point and the patch as small. Find the "
      "solid angle the patch subtends at the lamp, the lamp's intensity, the irradiance on the patch "
      "and the power it receives.";
  e.hint =
      "The patch's projected area is $A\\cos\\theta$, and a solid angle is a projected area over the "
      "distance "
      "squared. A point radiating equally in all directions spreads its power over $4\\pi$ steradians.";
  e.solution = {
      "The patch's area is $A = " + num(side) + "^2 = " + num(area, 6) +
          "$ m², its projected area $A\\cos\\theta = " + num(area, 6) + " \\times " + num(cosine, 6) + " = " +
          num(area * cosine, 6) + "$ m².",
      "Solid angle: $\\Omega \\approx A\\cos\\theta / r^2 = " + num(area * cosine, 6) + " / " +
          num(r * r, 6) + " = " + num(omega, 6) + "$ sr.",
      "Intensity of an isotropic point source: $I = \\Phi / (4\\pi) = " + num(power) + " / " +
          num(4 * kPi, 6) + " = " + num(intensity, 6) + "$ W/sr.",
      "Irradiance (the cosine law and the inverse-square law): $H = I\\cos\\theta / r^2 = " +
          num(intensity, 6) + " \\times " + num(cosine, 6) + " / " + num(r * r, 6) + " = " + num(H, 6) +
          "$ W/m².",
      "Power received: $\\Phi_A = H A = I\\,\\Omega = " + num(received, 6) +
          "$ W, the share $\\Omega / (4\\pi) = " + num(omega / (4 * kPi), 6) + "$ of the lamp's power.",
  };
  e.questions = {
      {"omega",
       "solid angle $\\Omega$ in sr",
       omega,
       tolerance(omega, 0.005, 1e-9),
       false,
       {{"the cosine left out (A / r^2)", area / (r * r)},
        {"divided by r, not r^2", area * cosine / r},
        {"the sine of the tilt used for its cosine", area * std::sin(tiltDegrees * kPi / 180) / (r * r)}}},
      {"I",
       "intensity $I$ in W/sr",
       intensity,
       tolerance(intensity, 0.005, 1e-9),
       false,
       {{"the power spread over a hemisphere (2 pi) instead of the sphere (4 pi)", power / (2 * kPi)},
        {"the power divided by pi (a Lambertian emitter's on-axis intensity)", power / kPi},
        {"the power spread over 4 pi r^2 (that is the irradiance of a facing patch)",
         power / (4 * kPi * r * r)}}},
      {"H",
       "irradiance $H$ in W/m²",
       H,
       tolerance(H, 0.005, 1e-9),
       false,
       {{"the cosine left out (I / r^2)", intensity / (r * r)},
        {"divided by r, not r^2", intensity * cosine / r},
        {"the power used for the intensity (no 4 pi)", power * cosine / (r * r)},
        {"the power received given for the irradiance (multiplied by A)", received}}},
      {"P",
       "power received $\\Phi_A$ in W",
       received,
       tolerance(received, 0.005, 1e-12),
       false,
       {{"the cosine left out", intensity * area / (r * r)},
        {"divided by r, not r^2", intensity * area * cosine / r}}},
  };
  return e;
}

}  // namespace rt::homework
