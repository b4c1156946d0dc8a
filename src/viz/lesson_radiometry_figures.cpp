#include "viz/lesson_radiometry_figures.h"

#include <cmath>
#include <stdexcept>

#include "viz/chart.h"
#include "viz/solid_angle_view.h"

namespace rt::viz::detail {

std::string renderRadiometryView(lesson::View view, const lesson::StepResult& r, const StepFigureSettings& s,
                                 const std::string& path) {
  if (!r.radiometry) throw std::runtime_error(path + ": the step is not a radiometry step");
  const lesson::RadiometryData& d = *r.radiometry;
  const std::string where = "r = " + formatted("%.3g", d.distance) + " m";
  switch (view) {
    case lesson::View::SolidAngle: {
      SolidAngleViewOptions o;
      o.size = {s.width, s.height, 96.0};
      writeSolidAngleFigure(solidAngleConstruction(d.point, d.patch, d.solidAngle, d.smallPatch), o, path);
      return "A square of side " + formatted("%.3g", d.side) + " m at " + where + ", tilted " +
             formatted("%.3g", d.tiltDegrees) +
             " degrees, projected onto the sphere about the point: the blue area over the radius squared is "
             "its solid angle, " +
             formatted("%.4f", d.solidAngle) + " sr (A cos(theta) / r^2 says " +
             formatted("%.4f", d.smallPatch) + " sr)";
    }
    case lesson::View::CosineLaw: {
      const Series law{"I cos(theta) / r^2", d.tilts, d.cosineLaw};
      const Series mean{"exact: I Omega / A", d.tilts, d.patchMean};
      // The step's tilt: a line up to the cosine law's value there (a chart line needs two points).
      const double cosine = std::cos(d.tiltDegrees * M_PI / 180);
      const Series here{"this step's tilt",
                        {d.tiltDegrees, d.tiltDegrees},
                        {0.0, d.intensity * cosine / (d.distance * d.distance)}};
      ChartOptions o{"Irradiance against tilt (" + where + ")",
                     "tilt theta (degrees)",
                     "irradiance (W/m^2)",
                     false,
                     false,
                     s.width,
                     s.height};
      writeLineChart({law, mean, here}, o, path);
      return "Irradiance on the patch from an isotropic point source of " + formatted("%.3g", d.power) +
             " W at " + where +
             " against the patch's tilt: the cosine law, and the exact mean over a patch "
             "of side " +
             formatted("%.3g", d.side) + " m";
    }
    case lesson::View::InverseSquare: {
      const Series point{"point emitter", d.distances, d.pointSource};
      const Series square{"square, same power", d.distances, d.squareSource};
      ChartOptions o{"Irradiance against distance",
                     "distance r (m)",
                     "irradiance (W/m^2)",
                     true,
                     true,
                     s.width,
                     s.height};
      // The step's distance: the gap between the two laws there.
      const Series here{"this step's distance",
                        {d.distance, d.distance},
                        {r.values.at("H.point"), r.values.at("H.square")}};
      writeLineChart({point, square, here}, o, path);
      return "Irradiance on a point facing a Lambertian point emitter (Phi / (pi r^2)) and a square of "
             "side " +
             formatted("%.3g", d.side) + " m emitting the same power, " + formatted("%.3g", d.power) +
             " W, against distance, log-log: the point law's slope is -2; the two agree within 1% beyond " +
             formatted("%.3g", d.onePercentDistance) + " m and part near the square";
    }
    default:
      throw std::runtime_error(path + ": not a radiometry view");
  }
}

}  // namespace rt::viz::detail
