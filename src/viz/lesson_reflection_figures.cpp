#include "viz/lesson_reflection_figures.h"

#include <cmath>
#include <stdexcept>

#include "viz/chart.h"
#include "viz/image_panels.h"
#include "viz/scene_view.h"

namespace rt::viz::detail {
namespace {

std::string modelText(const Brdf& b) {
  switch (b.model) {
    case BrdfModel::Lambertian:
      return "Lambertian, rho = " + formatted("%.2f", b.diffuse);
    case BrdfModel::Mirror:
      return "ideal mirror, a delta reflecting " + formatted("%.2f", b.specular);
    case BrdfModel::Phong:
      return "Phong, q = " + formatted("%g", b.exponent) + ", k_d = " + formatted("%.2f", b.diffuse) +
             ", k_s = " + formatted("%.2f", b.specular);
    case BrdfModel::Ward:
      return "Ward, alpha_x = " + formatted("%.3f", b.alphaX) + ", alpha_y = " + formatted("%.3f", b.alphaY) +
             ", k_d = " + formatted("%.2f", b.diffuse) + ", k_s = " + formatted("%.2f", b.specular);
  }
  return "";
}

}  // namespace

std::string renderReflectionView(lesson::View view, const lesson::Step& step, const lesson::StepResult& r,
                                 const StepFigureSettings& s, const std::string& path) {
  if (!r.reflection) throw std::runtime_error(path + ": the step is not a reflection step");
  const lesson::ReflectionData& d = *r.reflection;
  const std::string incidence = formatted("%g", d.incidenceDegrees) + " degrees";
  switch (view) {
    case lesson::View::Lobe: {
      const Mesh mesh = buildMesh(d.lobeScene);
      SceneViewOptions o;
      o.colouring = SceneColouring::Reflectance;
      o.image.width = s.width;
      o.image.height = s.height;
      o.caption = d.brdf.model == BrdfModel::Mirror ? "Mirror: all of the light leaves along one direction"
                                                    : "f_r cos(theta) for light from " + incidence;
      writeSceneFigure(mesh, d.lobeScene.cameraOrDefault(), SceneViewData{}, o, path);
      if (d.brdf.model == BrdfModel::Mirror)
        return "The BRDF of an ideal mirror reflecting " + formatted("%.2f", d.brdf.specular) +
               ", for light arriving " + incidence +
               " from the normal (the grey shaft; the blue one is the normal): a delta, drawn as a spike "
               "along "
               "the mirror direction as long as the fraction it reflects";
      return "The lobe of the BRDF (" + modelText(d.brdf) + ") for light arriving " + incidence +
             " from the normal (the grey shaft; the blue one is the normal): its distance from the point in "
             "each direction is f_r cos(theta), the light leaving that way, drawn to one size (peak " +
             formatted("%.3g", d.lobe.peak) + " per steradian)";
    }
    case lesson::View::PhongSweep: {
      std::vector<Series> series;
      // The step's own exponent is named, or drawn on top when the sweep does not hold it.
      bool drawn = false;
      for (std::size_t k = 0; k < d.exponents.size(); ++k) {
        const bool own = d.exponents[k] == d.brdf.exponent;
        drawn |= own;
        series.push_back({"q = " + formatted("%g", d.exponents[k]) + (own ? " (this step)" : ""), d.angles,
                          d.cosinePowers[k]});
      }
      if (!drawn) {
        Series own{"this step: q = " + formatted("%g", d.brdf.exponent), d.angles, {}};
        for (double degrees : d.angles)
          own.y.push_back(std::pow(std::cos(degrees * M_PI / 180), d.brdf.exponent));
        series.push_back(own);
      }
      ChartOptions o{"Phong's lobe cos^q(alpha)",
                     "alpha, from the mirror direction (degrees)",
                     "cos^q(alpha)",
                     false,
                     false,
                     s.width,
                     s.height};
      o.markers = false;
      writeLineChart(series, o, path);
      return "cos^q(alpha) against the angle alpha between the mirror direction and the viewer, for q = 1, "
             "2, 4, ..., 128 and the step's own q: the larger q, the narrower and sharper the highlight";
    }
    case lesson::View::Albedo: {
      const Series albedo{"directional albedo", d.incidences, d.albedo};
      const Series bound{"k_d + k_s",
                         {d.incidences.front(), d.incidences.back()},
                         {d.brdf.diffuse + d.brdf.specular, d.brdf.diffuse + d.brdf.specular}};
      ChartOptions o{"Reflected fraction against incidence",
                     "angle of incidence (degrees)",
                     "directional albedo",
                     false,
                     false,
                     s.width,
                     s.height};
      writeLineChart({albedo, bound}, o, path);
      return "The fraction of the light arriving from each angle that the " + modelText(d.brdf) +
             " BRDF reflects into the whole hemisphere, integrated numerically: never more than k_d + k_s";
    }
    case lesson::View::PhongLocal: {
      if (d.local.pixels.empty()) throw std::runtime_error(path + ": the step lit no scene");
      ImagePanelsOptions o;
      o.size = {s.width, s.height, 96.0};
      o.title = "Local illumination against radiosity";
      o.exposure = step.parameters.exposure;
      o.toneMap = toneMapFromName(step.parameters.toneMap);
      o.srgbGamma = step.parameters.gamma;
      // One exposure, the radiosity image's: equal light looks equal in both.
      writeImagePanelsFigure({{"Radiosity (" + std::to_string(r.mesh.size()) + " elements)", d.radiosity},
                              {"Phong + ambient " + formatted("%.3g", d.ambient.mean()) + " W/m^2", d.local}},
                             o, path);
      return "The radiosity solution's elements (left) and the same room lit locally (right): direct light "
             "from the lamp with shadows and Phong highlights (q = " +
             formatted("%g", d.brdf.exponent) + ", specular fraction " +
             formatted("%.2f", step.parameters.specularFraction) +
             "), and a constant ambient term in place of every interreflection";
    }
    default:
      throw std::runtime_error(path + ": not a reflection view");
  }
}

}  // namespace rt::viz::detail
