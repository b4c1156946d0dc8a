// The radiometry stage: one square patch seen from one point, built from the step's `patch-distance`,
// `patch-tilt` and `patch-size` (no scene file). It measures the patch's solid angle exactly and by the
// small-patch approximation, lights it with an isotropic point source at the point (the cosine law), and
// compares a point emitter with a square emitter of the same power along the axis (the inverse-square law).
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "core/formfactor/analytic.h"
#include "core/polygon.h"
#include "core/radiometry.h"
#include "lesson/radiometry_data.h"
#include "lesson/step_stages.h"

namespace rt::lesson::detail {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kPower = 100.0;  // W: the sources' radiant flux, a bright lamp's

// The sun at noon on the solstices, for the cosine law's winter and summer: Ithaca, New York (the Cornell
// box's home), and the tilt of the Earth's axis.
constexpr double kLatitude = 42.44;   // degrees north
constexpr double kObliquity = 23.44;  // degrees

double radians(double degrees) {
  return degrees * kPi / 180.0;
}

// A square of side `side` centred on (0, 0, distance), its normal turned by `tilt` (radians) away from the
// direction to the origin about the x axis; counter-clockwise seen from the origin's side.
Polygon squareAt(double distance, double tilt, double side) {
  const Vec3 centre(0, 0, distance), n(0, std::sin(tilt), -std::cos(tilt));
  const Vec3 u(1, 0, 0), v = n.cross(u);  // u x v = n
  const double h = 0.5 * side;
  return {centre + h * (-u - v), centre + h * (u - v), centre + h * (u + v), centre + h * (-u + v)};
}

// Irradiance on a point at the origin facing +z from a Lambertian square of side `side` and power `power`
// facing it at `distance`: its exitance times the point-to-square form factor.
double squareIrradiance(double distance, double side, double power) {
  const Vec3 up(0, 0, 1);
  return power / (side * side) * pointToPolygonFormFactor(Vec3::Zero(), up, squareAt(distance, 0, side));
}

// ... and from a Lambertian point emitter of the same power facing it: intensity Phi / pi on its axis.
double pointIrradiance(double distance, double power) {
  return power / (kPi * distance * distance);
}

// The distance beyond which the point emitter's irradiance is within 1% of the square's. The point law
// overestimates (every part of the square is farther and seen more obliquely than its centre), by less the
// farther away: bisection on that monotone error.
double onePercentDistance(double side, double power) {
  double lo = 0.01 * side, hi = 1000 * side;
  for (int k = 0; k < 100; ++k) {
    const double mid = std::sqrt(lo * hi);
    const double error = pointIrradiance(mid, power) / squareIrradiance(mid, side, power) - 1;
    (error > 0.01 ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

// The scene the 3D view shows: the patch, and the point as a small square facing it. The source emits (the
// view outlines it): the point, a lamp lighting the patch, unless the step compares the square as a source.
Scene radiometryScene(const Polygon& patch, double distance, double side, bool squareEmits) {
  Scene s;
  s.name = "A patch seen from a point";
  const Rgb light = Rgb::Constant(1.0), none = Rgb::Zero(), white = Rgb::Constant(0.6);
  s.materials = {{"patch", white, squareEmits ? light : none}, {"point", white, squareEmits ? none : light}};
  s.surfaces = {{"patch", 0}, {"point", 1}};
  const double e = 0.03 * std::max(distance, side);
  const Polygon point{{-e, -e, 0}, {e, -e, 0}, {e, e, 0}, {-e, e, 0}};
  addScenePatch(s, patch, 0);
  addScenePatch(s, point, 1);
  const double size = std::max(distance, side);
  Camera camera;
  // From the side the patch turns towards and below its centre: both squares show their fronts.
  camera.position = Vec3(2.6 * size, 1.7 * size, 0.35 * distance);
  camera.target = Vec3(0, 0, 0.5 * distance);
  camera.up = Vec3(0, 0, 1);
  s.camera = camera;
  return s;
}

}  // namespace

void computeRadiometry(StageContext& c) {
  const StepParameters& p = c.parameters;
  StepResult& r = c.result;
  auto data = std::make_shared<RadiometryData>();
  RadiometryData& d = *data;
  d.distance = p.patchDistance;
  d.tiltDegrees = p.patchTilt;
  d.side = p.patchSize;
  d.power = kPower;
  d.intensity = kPower / (4 * kPi);
  d.patch = squareAt(d.distance, radians(d.tiltDegrees), d.side);
  d.solidAngle = polygonSolidAngle(d.point, d.patch);
  d.smallPatch = smallPatchSolidAngle(d.point, d.patch);

  const double area = d.side * d.side, r2 = d.distance * d.distance;
  for (int degrees = 0; degrees < 90; degrees += 3) {
    const Polygon tilted = squareAt(d.distance, radians(degrees), d.side);
    d.tilts.push_back(degrees);
    d.cosineLaw.push_back(d.intensity * std::cos(radians(degrees)) / r2);
    d.patchMean.push_back(d.intensity * polygonSolidAngle(d.point, tilted) / area);
  }
  // From a tenth of the side, where the square's irradiance nears its exitance, to fifty sides away.
  for (int k = 0; k <= 30; ++k) {
    const double distance = d.side * 0.1 * std::pow(500.0, k / 30.0);
    d.distances.push_back(distance);
    d.pointSource.push_back(pointIrradiance(distance, kPower));
    d.squareSource.push_back(squareIrradiance(distance, d.side, kPower));
  }
  d.onePercentDistance = onePercentDistance(d.side, kPower);

  auto& v = r.values;
  v["distance"] = d.distance;
  v["tilt"] = d.tiltDegrees;
  v["size"] = d.side;
  v["area"] = area;
  v["solid-angle"] = d.solidAngle;
  v["solid-angle.approx"] = d.smallPatch;
  v["solid-angle.error"] = d.smallPatch / d.solidAngle - 1;
  v["cos-tilt"] = std::cos(radians(d.tiltDegrees));
  v["power"] = kPower;
  v["intensity"] = d.intensity;
  v["H.facing"] = d.intensity / r2;
  v["H.tilted"] = d.intensity * std::cos(radians(d.tiltDegrees)) / r2;
  v["H.patch"] = d.intensity * d.solidAngle / area;
  v["patch.flux"] = d.intensity * d.solidAngle;
  v["exitance"] = kPower / area;
  v["radiance"] = kPower / area / kPi;
  v["intensity.square"] = kPower / kPi;
  v["H.point"] = pointIrradiance(d.distance, kPower);
  v["H.square"] = squareIrradiance(d.distance, d.side, kPower);
  v["point-error"] = v["H.point"] / v["H.square"] - 1;
  v["one-percent-distance"] = d.onePercentDistance;
  v["one-percent-sides"] = d.onePercentDistance / d.side;
  v["cosine-integral.rings"] = 1000;
  v["cosine-integral"] = hemisphereCosineIntegral(1000);
  v["latitude"] = kLatitude;
  v["sun.summer"] = 90 - kLatitude + kObliquity;
  v["sun.winter"] = 90 - kLatitude - kObliquity;
  // Horizontal ground: the sun's rays make 90 degrees minus its elevation with the ground's normal.
  v["winter-summer"] = std::sin(radians(v["sun.winter"])) / std::sin(radians(v["sun.summer"]));

  const auto& views = c.step.views;
  const bool squareEmits = std::find(views.begin(), views.end(), View::InverseSquare) != views.end();
  r.scene = radiometryScene(d.patch, d.distance, d.side, squareEmits);
  r.mesh = buildMesh(r.scene);
  r.camera = r.scene.cameraOrDefault();
  v["elements"] = static_cast<double>(r.mesh.size());
  r.radiometry = std::move(data);
}

}  // namespace rt::lesson::detail
