// The reflection stage: one BRDF (core/brdf.h) chosen by `brdf-model`, `phong-exponent`,
// `specular-fraction` and `anisotropy`, lit from `incidence-angle`. It measures the BRDF's directional albedo
// (energy conservation) and reciprocity, evaluates it for a worked example, and draws its lobe. Without a
// scene the lobe is the step's scene, so that the app's 3D view shows it and turns it; with one, the stage
// also lights the scene by Phong local illumination plus an ambient term and solves it by radiosity, so that
// the two pictures stand side by side.
#include <cmath>
#include <memory>
#include <numbers>

#include "core/brdf_integrals.h"
#include "core/pathtrace/image_compare.h"
#include "core/pathtrace/local_illumination.h"
#include "core/polygon.h"
#include "lesson/reflection_data.h"
#include "lesson/step_stages.h"
#include "lesson/traced_pictures.h"

namespace rt::lesson::detail {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kReflectance = 0.8;   // k_d + k_s of the lobe viewer's material: white paint's
constexpr double kViewDegrees = 30.0;  // the worked example's viewer, on the mirror side of the normal
constexpr double kBeam = 100.0;        // W/m^2: the worked example's irradiance from a distant lamp
constexpr int kImageSize = 200;        // pixels along each side of the local and radiosity pictures
constexpr int kLightSamples = 16;      // shadow rays per pixel ray of the local picture
constexpr int kPixelSamples = 4;       // jittered rays per pixel of both pictures (smooth edges)

double radians(double degrees) {
  return degrees * kPi / 180.0;
}

// The lobe on a grey square of the surface, the normal, and the incoming ray (an emitter, so that the views
// outline it as the light), seen from in front of the plane of incidence and above.
Scene lobeScene(const BrdfLobe& lobe, const Vec3& wi) {
  Scene s;
  s.name = "A BRDF lobe";
  const Rgb none = Rgb::Zero();
  s.materials = {{"lobe", Rgb(0.85, 0.55, 0.2), none},
                 {"surface", Rgb::Constant(0.45), none},
                 {"normal", Rgb(0.3, 0.45, 0.8), none},
                 {"incoming", Rgb::Constant(0.6), Rgb::Constant(1.0)}};
  s.surfaces = {{"lobe", 0}, {"surface", 1}, {"normal", 2}, {"incoming", 3}};
  for (const Polygon& t : lobe.triangles) addScenePatch(s, t, 0);
  const double h = 1.3;
  addScenePatch(s, {Vec3(-h, -h, 0), Vec3(h, -h, 0), Vec3(h, h, 0), Vec3(-h, h, 0)}, 1);
  for (const Polygon& side : prism(Vec3(0, 0, 0.005), Vec3(0, 0, 1.15), 0.008)) addScenePatch(s, side, 2);
  for (const Polygon& side : prism(1.5 * wi, 0.02 * wi, 0.015)) addScenePatch(s, side, 3);
  Camera camera;
  camera.position = Vec3(0.6, -4.2, 2.4);
  camera.target = Vec3(0, 0, 0.45);
  camera.up = Vec3(0, 0, 1);
  camera.fovYDegrees = 38;
  s.camera = camera;
  return s;
}

// Phong local illumination and the radiosity solution of the step's scene through its camera.
void lightTheScene(StageContext& c, ReflectionData& d) {
  StepResult& r = c.result;
  r.method = c.method();
  r.F = c.formFactors(r.mesh, r.method, "method", r.formFactorStats);
  const RadiositySystem system = RadiositySystem::fromMesh(r.mesh, *r.F);
  r.runs.push_back(runSolver(c, c.parameters.solver, system, r.B, c.parameters.solver, true));
  const RgbField direct = (r.mesh.reflectance.array() * ((*r.F) * r.mesh.emission).array()).matrix();
  d.ambient = classicAmbient(r.mesh, direct, c.parameters.ambientLight);

  // The ambient term is a constant added to the picture: a new ambient light reuses the rest.
  const std::string key = "local illumination|" + picturesKey(c, {"ambient-light"});
  std::shared_ptr<const LitPictures> lit = c.runner.keptPictures<LitPictures>(key);
  if (!lit) {
    const TracingScene tracing(r.scene);
    LocalIlluminationOptions o;
    o.specularFraction = c.parameters.specularFraction;
    o.exponent = c.parameters.phongExponent;
    o.lightSamples = kLightSamples;
    o.pixelSamples = kPixelSamples;
    auto rendered = std::make_shared<LitPictures>();
    rendered->local = renderLocalIlluminationParts(tracing, r.camera, kImageSize, kImageSize, o);
    const RayScene rays(r.mesh);
    rendered->radiosity = renderElements(r.mesh, r.B, rays, r.camera, kImageSize, kImageSize, kPixelSamples);
    c.runner.keepPictures<LitPictures>(key, rendered);
    lit = std::move(rendered);
  }
  d.lit = lit;
  d.local = withAmbient(lit->local, d.ambient);
  d.radiosity = lit->radiosity;
  auto& v = r.values;
  v["ambient"] = d.ambient.mean();
  v["light-samples"] = kLightSamples;
  v["image.local.mean"] = imageMean(d.local);
  v["image.radiosity.mean"] = imageMean(d.radiosity);
  v["image.local-ratio"] = v["image.local.mean"] / v["image.radiosity.mean"];
  addSurfaceValues(r, "B", r.B);
}

}  // namespace

void computeReflection(StageContext& c) {
  const StepParameters& p = c.parameters;
  StepResult& r = c.result;
  const auto model = brdfModelFromName(p.brdfModel);
  if (!model) c.fail("brdf-model", "unknown BRDF model '" + p.brdfModel + "'");
  auto data = std::make_shared<ReflectionData>();
  ReflectionData& d = *data;
  d.brdf = makeBrdf(*model, kReflectance, p.specularFraction, p.phongExponent, p.anisotropy);
  d.incidenceDegrees = p.incidenceAngle;
  // The light in the plane of x, on the -x side: its mirror direction leans towards +x.
  d.wi = directionAt(radians(p.incidenceAngle), kPi);
  d.lobe = brdfLobe(d.brdf, d.wi);

  for (int degrees = 0; degrees < 90; degrees += 3) {
    d.incidences.push_back(degrees);
    d.albedo.push_back(directionalAlbedo(d.brdf, directionAt(radians(degrees), kPi), 128, 256));
  }
  for (double q = 1; q <= 128; q *= 2) {
    d.exponents.push_back(q);
    d.cosinePowers.emplace_back();
  }
  for (int degrees = 0; degrees <= 90; ++degrees) {
    d.angles.push_back(degrees);
    for (std::size_t k = 0; k < d.exponents.size(); ++k)
      d.cosinePowers[k].push_back(std::pow(std::cos(radians(degrees)), d.exponents[k]));
  }

  const Brdf& b = d.brdf;
  auto& v = r.values;
  v["reflectance"] = kReflectance;
  v["kd"] = b.diffuse;
  v["ks"] = b.specular;
  v["q"] = b.exponent;
  v["alpha-x"] = b.alphaX;
  v["alpha-y"] = b.alphaY;
  v["alpha"] = wardAlphaForExponent(b.exponent);
  v["incidence"] = d.incidenceDegrees;
  v["phong-normalisation"] = phongNormalisation(b.exponent);
  v["half-width"] = std::acos(std::pow(0.5, 1 / std::max(b.exponent, 1e-9))) * 180 / kPi;
  v["f.diffuse"] = b.diffuse / kPi;
  v["f.peak"] = evaluateBrdf(b, d.wi, mirrorDirection(d.wi));
  v["delta"] = deltaReflectance(b, d.wi);
  v["lobe.peak"] = d.lobe.peak;
  v["albedo"] = directionalAlbedo(b, d.wi);
  v["albedo.normal"] = directionalAlbedo(b, Vec3::UnitZ());
  v["albedo.grazing"] = d.albedo.back();
  v["albedo.grazing-angle"] = d.incidences.back();
  double largest = 0;
  for (double a : d.albedo) largest = std::max(largest, a);
  v["albedo.max"] = largest;
  v["reciprocity-error"] = reciprocityError(b, 2000, 1);
  v["lambert.albedo"] = directionalAlbedo(makeBrdf(BrdfModel::Lambertian, kReflectance, 0, 1, 1), d.wi);
  // The worked example: a distant lamp gives the surface the irradiance kBeam from w_i; a viewer looks from
  // kViewDegrees on the mirror side. L_o = f_r H (the lamp's solid angle is small: L_i cos(theta_i) dw = H).
  const Vec3 wo = directionAt(radians(kViewDegrees), 0);
  const double cosAlpha = mirrorDirection(d.wi).dot(wo);
  v["view"] = kViewDegrees;
  v["example.alpha"] = std::acos(std::clamp(cosAlpha, -1.0, 1.0)) * 180 / kPi;
  v["example.cos-alpha"] = cosAlpha;
  v["example.cos-alpha-q"] = cosAlpha > 0 ? std::pow(cosAlpha, b.exponent) : 0.0;
  v["example.f"] = evaluateBrdf(b, d.wi, wo);
  v["example.f-specular"] = v["example.f"] - (b.model == BrdfModel::Mirror ? 0.0 : b.diffuse / kPi);
  v["example.H"] = kBeam;
  v["example.L"] = v["example.f"] * kBeam;
  v["example.L-diffuse"] = b.diffuse / kPi * kBeam;
  v["example.L-specular"] = v["example.f-specular"] * kBeam;
  v["example.L-lambert"] = kReflectance / kPi * kBeam;

  if (c.step.scene.empty()) {
    r.scene = lobeScene(d.lobe, d.wi);
    r.mesh = buildMesh(r.scene);
    r.camera = r.scene.cameraOrDefault();
    v["elements"] = static_cast<double>(r.mesh.size());
  } else {
    lightTheScene(c, d);
  }
  d.lobeScene = r.scene.patches.empty() || !c.step.scene.empty() ? lobeScene(d.lobe, d.wi) : r.scene;
  r.reflection = std::move(data);
}

}  // namespace rt::lesson::detail
